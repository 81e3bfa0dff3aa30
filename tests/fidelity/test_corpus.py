"""Every corpus case through launcher, compared with what the real tool did (expected/).

The recordings come from real roslaunch and real ros2 launch (tests/fidelity/record.py), so
this test needs no ROS. A difference fails the case unless choices.py lists it, with the
reason, as launcher's deliberate choice; then launcher must give the chosen outcome instead.
The cases run a few at a time (each is mostly waiting on process start) and every test
compares one case.
"""

from __future__ import annotations

import difflib
import json
import os
import tempfile
import time
import uuid
from concurrent.futures import Future, ThreadPoolExecutor
from pathlib import Path

import pytest

from tests.fidelity.choices import CHOICES
from tests.fidelity.corpus import Case, cases
from tests.fidelity.known import KNOWN_DIFFERENCES
from tests.fidelity.normalise import outcome
from tests.fidelity.record import EXPECTED
from tests.fidelity.runner import launcher_tool
from tests.support.processes import tagged_processes

CASES = cases()
JOBS = 3
AHEAD = 2 * JOBS  # cases started before their test asks, so that JOBS are always running


class Runs:
    """Each case's launcher outcome, computed a few at a time: a test's case, and the cases
    of the next tests in the session's order, which are most often this process's next ones
    (pytest-xdist hands a worker its tests in runs of neighbours; a case it never asks for is
    computed and dropped, a few a worker at most)."""

    def __init__(self, order: list[Case], tag: str) -> None:
        self.order, self.tag = order, tag
        self.index = {case.name: i for i, case in enumerate(order)}
        self.scratch = Path(tempfile.mkdtemp(prefix="fidelity-"))
        self.pool = ThreadPoolExecutor(JOBS)
        self.futures: dict[str, Future] = {}
        self.environ = dict(os.environ)  # (read here: pytest changes it as tests run)

    def result(self, case: Case, timeout: float) -> tuple[dict, str]:
        start = self.index[case.name]
        for ahead in self.order[start:start + AHEAD + 1]:
            if ahead.name not in self.futures:
                self.futures[ahead.name] = self.pool.submit(self._run, ahead)
        return self.futures[case.name].result(timeout=timeout)

    def _run(self, case: Case) -> tuple[dict, str]:
        """The case's outcome, and what launcher printed (for the reader of a failure)."""
        # (a short folder: the graph's sockets live in it, and a socket's path is short)
        folder = self.scratch / f"case{self.index[case.name]}"
        tool = launcher_tool(case.flavour, folder / "run", self.environ)
        tool.env["LAUNCHER_TEST_TAG"] = self.tag
        run = tool.run(case, folder)
        return outcome(run, folder, case.flavour), run.output


@pytest.fixture(scope="module")
def runs(request):
    """The cases of this session's corpus tests, in their order."""
    chosen = [item.callspec.params["case"] for item in request.session.items
              if getattr(item, "callspec", None) and "case" in item.callspec.params
              and item.module.__name__ == __name__]
    corpus = Runs(chosen, uuid.uuid4().hex)
    yield corpus
    for future in corpus.futures.values():
        future.cancel()  # (cases run ahead that no test of this process will ask for)
    corpus.pool.shutdown(wait=True)
    deadline = time.monotonic() + 5
    while tagged_processes(corpus.tag) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert not tagged_processes(corpus.tag), "the corpus's launches left processes behind"


def recorded(case: Case) -> dict:
    path = EXPECTED / f"{case.name}.json"
    assert path.exists(), f"{case.name} has no recording: python -m tests.fidelity.record --stale"
    data = json.loads(path.read_text())
    assert data["case"] == case.digest, \
        f"{case.name} changed since it was recorded: python -m tests.fidelity.record --stale"
    return data["outcome"]


def _marked(case: Case):
    if case.name not in KNOWN_DIFFERENCES:
        return case
    return pytest.param(case, marks=pytest.mark.xfail(
        strict=True, reason="a known difference, not yet fixed (tests/fidelity/known.py)"))


@pytest.mark.parametrize("case", [_marked(case) for case in CASES],
                         ids=[case.name for case in CASES])
def test_launcher_agrees_with_the_real_tool(case: Case, runs) -> None:
    expected = recorded(case)
    choice = CHOICES.get(case.name)
    if choice is not None:
        expected = choice.apply(expected)
    got, output = runs.result(case, timeout=120)
    assert got == expected, _difference(expected, got, choice) + \
        f"\nlauncher's output (its end):\n{output[-2000:]}"


def _difference(expected: dict, got: dict, choice) -> str:
    want = json.dumps(expected, indent=1, sort_keys=True).splitlines()
    have = json.dumps(got, indent=1, sort_keys=True).splitlines()
    diff = "\n".join(difflib.unified_diff(want, have, "the real tool" + (
        " (with launcher's listed choice)" if choice else ""), "launcher", lineterm=""))
    return f"launcher differs from the recording:\n{diff}"
