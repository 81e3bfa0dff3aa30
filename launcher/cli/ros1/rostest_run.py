"""The tests of one rostest launch, run one after the other once the launch's own nodes have
started: each test's node in the scope its `<test>` was met in, with rostest's
`--gtest_output=xml:PATH` on its command line, stopped at its time limit, run again while it
fails and retries are left; then the launch ends."""

from __future__ import annotations

import copy
import xml.etree.ElementTree as ET
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from launcher.api import Action, OnProcessExit, RegisterEventHandler
from launcher.compat.testing.junit import RESULTS_FLAG
from launcher.description.action import Replay
from launcher.description.actions.rostest import CollectedTest
from launcher.description.substitution import to_text
from launcher.runtime.service import LaunchService


@dataclass
class Outcome:
    """A test's result: cases run, failed and in error, and what went wrong."""
    name: str
    tests: int = 0
    failures: int = 0
    errors: int = 0
    details: list[str] = field(default_factory=list)

    @property
    def passed(self) -> bool:
        return self.tests > 0 and not self.failures and not self.errors


class StartTests(Action):
    """Visited after the launch's own actions: the first test starts."""

    def __init__(self, run: TestsRun) -> None:
        self.condition, self.where, self.run = None, None, run

    def execute(self, context: Any) -> Sequence[Action] | None:
        self.run.next()
        return None


class TestsRun:
    def __init__(self, service: LaunchService, results: Path) -> None:
        self.service, self.results = service, results
        self.collected: list[CollectedTest] = []  # (the launch's context collects them)
        self.outcomes: list[Outcome] = []
        self._index, self._attempt = 0, 0
        self._node: Any = None
        self._timer: Any = None
        self._timed_out = False

    def next(self) -> None:
        """Start the next test (or this one again), or end the launch after the last."""
        if self._index >= len(self.collected):
            self.service.shutdown("rostest: every test has run")
            return
        test = self.collected[self._index]
        target = self.results / f"rosunit-{test.name}.xml"
        target.unlink(missing_ok=True)
        node = copy.copy(test.node)
        if self._attempt:  # (the name was checked once, at the first attempt)
            node.unique = False
        node.arguments = (*to_text(node.arguments or ""), *to_text(f" {RESULTS_FLAG}{target}"))
        self._node, self._timed_out = node, False
        handler = RegisterEventHandler(OnProcessExit(target_action=node, on_exit=self._exited))
        self.service.schedule([Replay(snapshot=test.snapshot, actions=[handler, node])])
        self._timer = self.service.add_timer(test.time_limit, self._time_up)

    def _time_up(self) -> None:
        """The test ran past its time limit: it is stopped, and fails for it."""
        self._timed_out = True
        self.service.table.stop_started_by(self._node)

    def _exited(self, event: Any, _context: Any) -> None:
        if self._timer is not None:
            self._timer.cancel()
        test = self.collected[self._index]
        outcome = self._outcome(test, event.returncode)
        ending = self.service.shutting_down  # (a signal: what ran counts, nothing more runs)
        if not outcome.passed and self._attempt < test.retry and not ending:
            self._attempt += 1
        else:
            self.outcomes.append(outcome)
            self._index, self._attempt = self._index + 1, 0
        if not ending:
            self.next()

    def _outcome(self, test: CollectedTest, returncode: int | None) -> Outcome:
        outcome = Outcome(test.name)
        if self._timed_out:
            outcome.tests, outcome.errors = 1, 1
            outcome.details.append(f"test [{test.name}] ran past its time limit of "
                                   f"{test.time_limit:g} s and was stopped")
            return outcome
        report = self.results / f"rosunit-{test.name}.xml"
        if report.exists():
            return _read(report, outcome)
        # no results written (a test that is not a rostest.rosrun one): its exit status says
        outcome.tests = 1
        if returncode != 0:
            outcome.failures = 1
            outcome.details.append(f"test [{test.name}] exited with code {returncode} and "
                                   "wrote no results")
        return outcome

    def not_run(self) -> list[str]:
        """The tests the launch ended before."""
        return [test.name for test in self.collected[len(self.outcomes):]]


def _read(report: Path, outcome: Outcome) -> Outcome:
    """The counts and failures of a JUnit XML report."""
    root = ET.parse(report).getroot()
    for case in root.iter("testcase"):
        outcome.tests += 1
        for kind in ("failure", "error"):
            for found in case.findall(kind):
                setattr(outcome, f"{kind}s", getattr(outcome, f"{kind}s") + 1)
                outcome.details.append(f"{case.get('name')}: {found.get('message', kind)}")
    return outcome
