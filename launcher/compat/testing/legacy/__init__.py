"""launch_testing.legacy's LaunchTestService, the launch tests of before launch_testing's
active tests. Fixture processes run beside the tests (one that dies shuts the launch down);
test actions pass when their process exits with 0 (other actions: once they have run); output
tests pass when a process prints what they expect. The launch ends once every test is done,
and `run` gives the exit status of the first failure.

    ld = LaunchDescription(); lts = LaunchTestService()
    lts.add_test_action(ld, ExecuteProcess(cmd=[...]))
    ls = LaunchService(); ls.include_launch_description(ld)
    assert lts.run(ls) == 0
"""

from __future__ import annotations

from typing import Any

from launcher.api import (
    ExecuteProcess,
    OnProcessExit,
    OnProcessIO,
    OnShutdown,
    OpaqueFunction,
    RegisterEventHandler,
    Shutdown,
)

ARMED, FINISHED, DROPPED, FAILED, SUCCEEDED = "armed", "finished", "dropped", "failed", \
    "succeeded"


class LaunchTestService:
    """The state of each test (armed until it passes, fails or is dropped), and each failed
    process's exit status."""

    def __init__(self) -> None:
        self._tests: dict[str, str] = {}
        self._processes_rc: dict[str, int] = {}

    # --- a test's state; each gives the actions that follow (a shutdown when all are done) ---
    def _arm(self, test_name: str) -> None:
        assert test_name not in self._tests
        self._tests[test_name] = ARMED

    def _all_done(self) -> list[Any] | None:
        if all(status != ARMED for status in self._tests.values()):
            return [Shutdown(reason="all tests finished")]
        return None

    def _finish(self, test_name: str) -> list[Any] | None:
        """Done, neither passed nor failed (its output is judged at shutdown)."""
        self._tests[test_name] = FINISHED
        return self._all_done()

    def _drop(self, test_name: str) -> None:
        self._tests[test_name] = DROPPED

    def _fail(self, test_name: str, reason: str) -> list[Any]:
        """Failed: the tests still armed are dropped, and the launch shuts down."""
        self._tests[test_name] = FAILED
        for name, status in self._tests.items():
            if status == ARMED:
                self._tests[name] = DROPPED
        return [Shutdown(reason=reason)]

    def _succeed(self, test_name: str, side_effect: str | None = None) -> list[Any]:
        self._tests[test_name] = SUCCEEDED
        done = self._all_done()
        if done:
            return done
        return [Shutdown(reason="shutdown after test")] if side_effect == "shutdown" else []

    # --- what a test file adds ----------------------------------------------------------------
    def add_fixture_action(self, launch_description: Any, action: Any,
                           exit_allowed: Any = (0,)) -> Any:
        """Add `action`, a fixture: when its process exits with a status not in
        `exit_allowed` (a list of statuses; or True: any) before the launch ends, the launch shuts
        down and `run` gives that status."""
        launch_description.add_action(action)
        if isinstance(action, ExecuteProcess):
            def fixture_exited(event: Any, context: Any) -> list[Any] | None:
                allowed = event.returncode in exit_allowed \
                    if isinstance(exit_allowed, list | tuple | set) else bool(exit_allowed)
                if _shutting_down(context) or allowed:
                    return None
                self._processes_rc[event.process_name] = event.returncode or 1
                return [Shutdown(reason=f"{event.process_name} fixture process died!")]

            launch_description.add_action(RegisterEventHandler(
                OnProcessExit(target_action=action, on_exit=fixture_exited)))
        return action

    def add_test_action(self, launch_description: Any, action: Any) -> Any:
        """Add `action`, a test: a process passes when it exits with 0 (else the launch
        shuts down, failed), another action once it has run."""
        test_name = f"test_{id(action)}"
        if isinstance(action, ExecuteProcess):
            def test_exited(event: Any, _context: Any) -> list[Any]:
                if event.returncode != 0:
                    self._processes_rc[event.process_name] = event.returncode
                    return self._fail(test_name, reason=f"{event.process_name} test failed!")
                return self._succeed(test_name)

            launch_description.add_action(RegisterEventHandler(
                OnProcessExit(target_action=action, on_exit=test_exited)))
            launch_description.add_action(action)
        else:  # (launcher's actions are complete once visited: no future to wait for)
            launch_description.add_action(action)
            launch_description.add_action(
                OpaqueFunction(function=lambda _context: self._succeed(test_name)))
        self._arm(test_name)
        return action

    def add_output_test(self, launch_description: Any, action: Any, output_test: Any,
                        test_suffix: str = "output", output_filter: Any = None,
                        side_effect: str | None = None) -> Any:
        """Test the stdout of `action`'s process with `output_test` (legacy.output's):
        it passes once every pattern was found (then `side_effect` 'shutdown' ends the
        launch), and fails when the launch ends first."""
        assert isinstance(action, ExecuteProcess)
        test_name = f"test_{id(action)}_{test_suffix}"
        buffer, collate, match, patterns = output_test
        keep = output_filter or (lambda text: text)
        assert any(patterns)
        state = {"out": buffer, "left": list(patterns)}

        def exited(_event: Any, _context: Any) -> list[Any] | None:
            # finished, not failed: the output still on its way is judged at shutdown
            return self._finish(test_name) if any(state["left"]) else None

        def shut_down(_event: Any, _context: Any) -> None:
            if any(state["left"]):
                self._fail(test_name, f"not all {_name(action)} output matched!")
            self._succeed(test_name, side_effect)

        def printed(event: Any, _context: Any = None) -> list[Any] | None:
            state["out"] = collate(state["out"], keep(_bytes(event.text)))
            state["left"] = [p for p in state["left"] if not match(state["out"], p)]
            return None if any(state["left"]) else self._succeed(test_name, side_effect)

        for handler in (OnProcessExit(target_action=action, on_exit=exited),
                        OnShutdown(on_shutdown=shut_down),
                        OnProcessIO(target_action=action, on_stdout=printed)):
            launch_description.add_action(RegisterEventHandler(handler))
        self._arm(test_name)
        return action

    def run(self, launch_service: Any, *args: Any, **kwargs: Any) -> int:
        """`launch_service.run(…)`; when that gives 0, the status of the first test process
        that failed, or 1 if a test failed, else 0."""
        rc = launch_service.run(*args, **kwargs)
        if rc == 0:
            default = 1 if FAILED in self._tests.values() else 0
            rc = next((code for code in self._processes_rc.values() if code != 0), default)
        return rc


def _shutting_down(context: Any) -> bool:
    service = getattr(context, "service", None)
    return bool(getattr(service, "shutting_down", False))


def _bytes(text: Any) -> bytes:
    """A line of output as bytes, with its line end (launcher's events give it as text)."""
    return text if isinstance(text, bytes) else (text + "\n").encode()


def _name(action: Any) -> str:
    details = action.process_details or {}
    return details.get("name", "process")
