"""One run of a launch test: the description launched in this thread (the launch service
handles the signals), the active tests in another once ReadyToTest is visited, the launch
shut down when they are done, then the post-shutdown tests. `run_once` gives the run a graph
of its own (`launcher test` and launch_testing's runner)."""

from __future__ import annotations

import sys
import threading
import unittest
from collections.abc import Callable
from typing import Any

from launcher.api import (
    LaunchDescription,
    OnProcessExit,
    OnProcessIO,
    OnProcessStart,
    RegisterEventHandler,
)
from launcher.compat.testing.io_handler import ActiveIoHandler
from launcher.compat.testing.junit import RecordingResult
from launcher.compat.testing.loader import bind
from launcher.compat.testing.proc_info_handler import ActiveProcInfoHandler
from launcher.compat.testing.records import ProcessInfo, ProcessOutput
from launcher.runtime.service import LaunchService

FOREVER = 365 * 24 * 3600.0  # s: the timer that keeps a keep_alive launch up


def run_tests(tests: unittest.TestSuite, stream: Any) -> unittest.TestResult:
    return unittest.TextTestRunner(stream=stream, verbosity=2,
                                   resultclass=RecordingResult).run(tests)


class ServiceProxy:
    """The `launch_service` active tests are given: calls from their thread, run on the
    launch's loop."""

    def __init__(self, service: LaunchService) -> None:
        self.service = service
        service.loop.open_posting()

    def start_action(self, action: Any) -> None:
        """Visit `action` (an ExecuteProcess, a description) in the running launch."""
        self.service.loop.call_soon_threadsafe(self.service.schedule, [action])

    def stop_action(self, action: Any) -> None:
        """Stop the processes `action` started."""
        self.service.loop.call_soon_threadsafe(self.service.table.stop_started_by, action)

    def shutdown(self) -> None:
        self.service.loop.call_soon_threadsafe(self.service.shutdown, "the tests are done")


class Worker:
    def __init__(self, run: Any, new_service: Callable[[], LaunchService],
                 arguments: dict[str, str], time_limit: float | None = None) -> None:
        """`new_service` makes the launch service once the description is known good (none is
        started for a test file that cannot run); `time_limit`: seconds the active tests may
        take (none: no limit, as launch_test)."""
        self.run, self.new_service, self.arguments = run, new_service, arguments
        self.service: Any = None
        self.time_limit = time_limit
        self.proc_info, self.proc_output = ActiveProcInfoHandler(), ActiveIoHandler()
        self.ready, self.done = threading.Event(), threading.Event()
        self.active_result: unittest.TestResult | None = None
        self.note = ""  # why the active tests did not run, or did not finish

    def execute(self, stream: Any) -> list[unittest.TestResult]:
        """The results of the active tests and of the post-shutdown tests."""
        description, context = self.run.description(self.ready.set)
        self.service = self.new_service()
        proxy = ServiceProxy(self.service)
        shared = {**context, **self.run.param_args, "test_args": dict(self.arguments)}
        bind(self.run.active, {**shared, "proc_info": self.proc_info,
                               "proc_output": self.proc_output, "launch_service": proxy})
        bind(self.run.post_shutdown, {**shared, "proc_info": self.proc_info.snapshot(),
                                      "proc_output": self.proc_output.snapshot()})
        if self.run.markers.get("keep_alive"):
            self.service.add_timer(FOREVER, lambda: None)
        if self.time_limit is not None:
            self.service.add_timer(self.time_limit, self._time_up)
        tests = threading.Thread(target=self._active, args=(proxy, stream),
                                 name="launch-test-active", daemon=True)
        tests.start()
        self.service.run(LaunchDescription([*self._recorders(), description]))
        if not self.done.is_set():
            self.note = self.note or "Processes under test stopped before tests completed"
            print(f"FAIL: {self.run}: {self.note}", file=stream)
            return [failed(self.run, self.note)]
        post = run_tests(self.run.post_shutdown, stream)
        return [result for result in (self.active_result, post) if result is not None]

    def _time_up(self) -> None:
        """The time limit has passed: a test still running is a failure, and the launch ends
        (everything it started stops; the test's thread is left to the process's end)."""
        if not self.done.is_set():
            self.note = f"the active tests did not finish within {self.time_limit:g} s"
            self.service.shutdown(f"time limit: {self.note}")

    def _active(self, proxy: ServiceProxy, stream: Any) -> None:
        if not self.ready.wait(self.run.timeout):
            self.note = (f"Timed out waiting for processes to start up: ReadyToTest was not "
                         f"reached in {self.run.timeout:g} s")
            proxy.shutdown()
            return
        try:
            self.active_result = run_tests(self.run.active, stream)
        finally:
            self.done.set()
            proxy.shutdown()

    def _recorders(self) -> list[Any]:
        """Event handlers that record each process's start, output and exit for the tests."""
        def started(event: Any, _context: Any) -> None:
            self.proc_output.track(event.action)
            self.proc_info.append(ProcessInfo(event.action, event.process_name, list(event.cmd),
                                              event.pid))

        def exited(event: Any, _context: Any) -> None:
            self.proc_info.append(ProcessInfo(event.action, event.process_name, list(event.cmd),
                                              event.pid, event.returncode))

        def printed(event: Any) -> None:  # (launch gives an output handler the event alone)
            self.proc_output.append(ProcessOutput(event.action, event.process_name, event.text,
                                                  event.stream))

        return [RegisterEventHandler(OnProcessStart(on_start=started)),
                RegisterEventHandler(OnProcessExit(on_exit=exited)),
                RegisterEventHandler(OnProcessIO(on_stdout=printed, on_stderr=printed))]


def run_once(run: Any, configurations: dict[str, str], *, debug: bool = False,
             time_limit: float | None = None) -> tuple[Worker, list[unittest.TestResult]]:
    """One launch of `run` (a TestRun) on a graph of its own (its run folder private and
    temporary), its tests printing on stderr: the worker, and the results."""
    from launcher.cli.launch_command import launch_service
    from launcher.cli.own_graph import own_graph
    from launcher.cli.workspace import load_index

    def new_service() -> LaunchService:
        return launch_service(configurations, load_index(), debug=debug)

    worker = Worker(run, new_service, configurations, time_limit)
    with own_graph("launch-test-"):
        return worker, worker.execute(sys.stderr)


def failed(run: Any, reason: str) -> unittest.TestResult:
    """A result with one failure: the run itself, for `reason`."""
    result = unittest.TestResult()

    class LaunchFailed(unittest.TestCase):
        def runTest(self) -> None:  # noqa: N802 - unittest's name
            self.fail(reason)

    case = LaunchFailed()
    case._testMethodName = "runTest"
    result.addFailure(case, (AssertionError, AssertionError(reason), None))
    result.testsRun = 1
    return result
