"""Run corpus cases through launcher and say which differ from their recording:
`python -m tests.fidelity.compare [--only TEXT]`. The test does the same, case by case; this
prints the whole picture at once (and what launcher printed for each case that differs)."""

from __future__ import annotations

import argparse
import json
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from tests.fidelity.choices import CHOICES
from tests.fidelity.corpus import Case, cases
from tests.fidelity.normalise import outcome
from tests.fidelity.record import EXPECTED
from tests.fidelity.runner import launcher_tool


def compare(case: Case, scratch: Path) -> tuple[bool, float, str]:
    """Whether launcher agrees on `case`, the seconds its run took, and its output (with,
    where it differs, both outcomes)."""
    folder = scratch / f"case-{case.digest[:10]}"  # (short: the graph's sockets live in it)
    started = time.monotonic()
    run = launcher_tool(case.flavour, folder / "run").run(case, folder)
    took = time.monotonic() - started
    expected = json.loads((EXPECTED / f"{case.name}.json").read_text())["outcome"]
    if case.name in CHOICES:
        expected = CHOICES[case.name].apply(expected)
    got = outcome(run, folder, case.flavour)
    if got == expected:
        return True, took, run.output
    both = json.dumps({"expected": expected, "launcher": got}, indent=1, sort_keys=True)
    return False, took, f"{run.output}\n{both}"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--only", default="")
    parser.add_argument("--jobs", type=int, default=3)
    parser.add_argument("--output", action="store_true", help="print what launcher printed and both outcomes")
    options = parser.parse_args()
    chosen = [case for case in cases() if options.only in case.name]
    scratch = Path(tempfile.mkdtemp(prefix="fidelity-compare-"))
    with ThreadPoolExecutor(options.jobs) as pool:
        results = list(pool.map(lambda case: compare(case, scratch), chosen))
    for case, (agrees, _, output) in zip(chosen, results, strict=True):
        if not agrees:
            print(f"differs: {case.name}")
            if options.output:
                print("    " + output.strip().replace("\n", "\n    "))
    print(f"{sum(r[0] for r in results)} of {len(chosen)} cases agree")


if __name__ == "__main__":
    main()
