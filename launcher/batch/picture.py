"""matrix.png: the table's grids as heat maps, one per job entry side by side, each cell
coloured by its pass fraction (red → green) and labelled `passed/run`."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from launcher.batch.matrix import JobPlan
from launcher.batch.results import JobResult
from launcher.batch.spec import BatchFile
from launcher.batch.table import Grid, grids

NO_MATPLOTLIB = "matrix.png not drawn: pip install 'launcher[plot]'"
CELL = 0.9  # inches per cell
DPI = 100


def write_matrix_png(path: Path, batch: BatchFile, plans: list[JobPlan],
                     results: dict[str, JobResult]) -> str | None:
    """None when drawn, else why not."""
    # matplotlib costs a second to import, and only this picture needs it
    try:
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure
    except ImportError:
        return NO_MATPLOTLIB
    drawn = grids(batch, plans, results)
    if not drawn:
        return "matrix.png not drawn: no jobs"
    width = sum(2.5 + CELL * len(g.columns) for g in drawn)
    height = 1.8 + CELL * max(len(g.rows) for g in drawn)
    figure = Figure(figsize=(width, height), dpi=DPI, layout="constrained")
    FigureCanvasAgg(figure)  # Agg: no display, the same picture on every machine
    ratios = [len(g.columns) for g in drawn]
    for axes, grid in zip(figure.subplots(1, len(drawn), squeeze=False,
                                          width_ratios=ratios)[0], drawn, strict=True):
        _heat_map(axes, grid)
    figure.suptitle(batch.title)
    path.parent.mkdir(parents=True, exist_ok=True)
    figure.savefig(path)
    return None


def _heat_map(axes: Any, grid: Grid) -> None:
    from matplotlib import colormaps

    colours = colormaps["RdYlGn"].with_extremes(bad="lightgrey")  # grey: nothing ran
    fractions = [[p / r if r else float("nan") for p, r in row] for row in grid.cells]
    axes.imshow(fractions, cmap=colours, vmin=0.0, vmax=1.0, aspect="auto")
    for y, row in enumerate(grid.cells):
        for x, (passed, run) in enumerate(row):
            dark = run and not 0.2 < passed / run < 0.8  # the colour map's ends are dark
            axes.text(x, y, f"{passed}/{run}", ha="center", va="center",
                      color="white" if dark else "black")
    axes.set_xticks(range(len(grid.columns)), grid.columns, rotation=30, ha="right")
    axes.set_yticks(range(len(grid.rows)), grid.rows)
    axes.set_ylabel(grid.corner)
    axes.set_title(grid.title, fontsize="medium")
