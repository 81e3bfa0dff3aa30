"""A batch's results over its matrix: per job entry a grid of `passed/run` (the table printed
at the end, and matrix.png's heat maps), and the one summary line."""

from __future__ import annotations

from collections import Counter

from launcher import records
from launcher.batch.matrix import JobPlan
from launcher.batch.progress import span
from launcher.batch.results import JobResult, Status
from launcher.batch.spec import BatchFile


@records.dataclass(frozen=True)
class Grid:
    """One job entry's results: rows × columns of (passed, run) over seeds and repeats."""

    title: str  # `drive (tests/drive_test.py)`
    corner: str  # the names of the rows' keys
    rows: list[str]
    columns: list[str]
    cells: list[list[tuple[int, int]]]


def grids(batch: BatchFile, plans: list[JobPlan], results: dict[str, JobResult]) -> list[Grid]:
    """Two keys: rows × columns; one: rows; none: one row; more: rows are combinations of
    all but the last key, columns the last."""
    made = []
    for number, entry in enumerate(batch.jobs):
        own = [p for p in plans if p.number == number]
        if own:
            made.append(_grid(f"{own[0].label} ({entry.file})", own, results))
    return made


def _grid(title: str, plans: list[JobPlan], results: dict[str, JobResult]) -> Grid:
    keys = list(dict.fromkeys(k for p in plans for k in p.varied))
    across = keys[-1] if len(keys) >= 2 else None
    down = keys[:-1] if across else keys

    def row(p: JobPlan) -> str:
        return ", ".join(p.varied.get(k, "") for k in down) or "all"

    def column(p: JobPlan) -> str:
        return f"{across}={p.varied.get(across, '')}" if across else "passed/run"

    rows = list(dict.fromkeys(map(row, plans)))
    columns = list(dict.fromkeys(map(column, plans)))
    passed: Counter[tuple[str, str]] = Counter()
    run: Counter[tuple[str, str]] = Counter()
    for plan in plans:
        result = results.get(plan.id)
        if result is not None and result.status is not Status.CANCELLED:
            run[row(plan), column(plan)] += 1
            passed[row(plan), column(plan)] += result.status is Status.PASS
    cells = [[(passed[r, c], run[r, c]) for c in columns] for r in rows]
    return Grid(title, ", ".join(down), rows, columns, cells)


def matrix_table(batch: BatchFile, plans: list[JobPlan],
                 results: dict[str, JobResult]) -> str:
    """Every entry's grid as aligned text columns, a blank line between entries."""
    return "\n\n".join(_text(grid) for grid in grids(batch, plans, results))


def _text(grid: Grid) -> str:
    table = [[grid.corner, *grid.columns]]
    table += [[name, *(f"{p}/{r}" for p, r in cells)]
              for name, cells in zip(grid.rows, grid.cells, strict=True)]
    widths = [max(len(line[i]) for line in table) for i in range(len(table[0]))]
    lines = [grid.title]
    for line in table:
        cells = [line[0].ljust(widths[0])]
        cells += [cell.rjust(width) for cell, width in zip(line[1:], widths[1:], strict=True)]
        lines.append("  " + "  ".join(cells).rstrip())
    return "\n".join(lines)


def summary_line(results: list[JobResult], wall_s: float, nodes: int) -> str:
    """`40 jobs: 38 passed, 1 failed, 1 error, 0 timed out, 0 cancelled in 2m41s (893
    jobs/hour) on 2 nodes`"""
    count = Counter(r.status for r in results)
    line = (f"{_plural(len(results), 'job')}: {count[Status.PASS]} passed, "
            f"{count[Status.FAIL]} failed, {_plural(count[Status.ERROR], 'error')}, "
            f"{count[Status.TIMEOUT]} timed out, {count[Status.CANCELLED]} cancelled "
            f"in {span(wall_s)}")
    if wall_s > 0:
        line += f" ({round(len(results) * 3600 / wall_s)} jobs/hour)"
    return f"{line} on {_plural(nodes, 'node')}"


def _plural(count: int, noun: str) -> str:
    return f"{count} {noun}" if count == 1 else f"{count} {noun}s"
