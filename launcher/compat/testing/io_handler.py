"""launch_testing's IoHandler (the output the post-shutdown tests get) and ActiveIoHandler
(what the active tests get: it can wait for a text)."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

from launcher.compat.testing.active import CONDITION, Active
from launcher.compat.testing.asserts import assertInStream
from launcher.compat.testing.records import ProcessOutput
from launcher.compat.testing.util import NoMatchingProcessException, resolveProcesses


class IoHandler:
    """Every piece of output in the order it came, and each process's own."""

    def __init__(self) -> None:
        self._sequence: list[ProcessOutput] = []
        self._by_action: dict[Any, list[ProcessOutput]] = {}

    def track(self, action: Any) -> None:
        self._by_action.setdefault(action, [])

    def append(self, output: ProcessOutput) -> None:
        self._sequence.append(output)
        self._by_action.setdefault(output.action, []).append(output)

    def __iter__(self) -> Iterator[ProcessOutput]:
        return iter(list(self._sequence))

    def processes(self) -> list[Any]:
        """The launch actions of the processes that printed something."""
        return [action for action, outputs in self._by_action.items() if outputs]

    def process_names(self) -> list[str]:
        """The names of the processes that printed something."""
        return [outputs[0].process_name for outputs in self._by_action.values() if outputs]

    def __getitem__(self, key: Any) -> list[ProcessOutput]:
        """A process's output, by its launch action or its name."""
        if isinstance(key, str):
            for outputs in self._by_action.values():
                if outputs and outputs[0].process_name == key:
                    return list(outputs)
            raise KeyError(key)
        return list(self._by_action[key])


class ActiveIoHandler(Active):
    """An IoHandler that the launch fills while the active tests wait on it."""

    _record = IoHandler
    io_event = CONDITION

    def track(self, action: Any) -> None:
        with self._changed:
            self._handler.track(action)
            self._changed.notify_all()

    def assertWaitFor(self, *args: Any, **kwargs: Any) -> None:  # noqa: N802
        """waitFor, and an AssertionError when the text did not come in time."""
        assert self.waitFor(*args, **kwargs), "Waiting for output timed out"

    def waitFor(self, expected_output: Any, process: Any = None,  # noqa: N802
                cmd_args: Any = None, *, strict_proc_matching: bool = True,
                output_filter: Any = None, timeout: float = 10,
                strip_ansi_escape_sequences: bool = True, stream: str = "stderr") -> bool:
        """Wait up to `timeout` seconds for `expected_output` (a text, a regular expression or
        a list of them in order) in `stream` of `process` (any process when None)."""
        def found() -> bool:
            try:
                assertInStream(self._handler, expected_output, process, cmd_args,
                               output_filter=output_filter,
                               strict_proc_matching=strict_proc_matching,
                               strip_ansi_escape_sequences=strip_ansi_escape_sequences,
                               stream=stream)
            except (NoMatchingProcessException, AssertionError):
                return False
            return True

        with self._changed:
            success = self._changed.wait_for(found, timeout=timeout)
        if not success:
            try:
                resolveProcesses(self, process=process, cmd_args=cmd_args,
                                 strict_proc_matching=False)
            except NoMatchingProcessException:
                raise Exception(f"After timeout, found no processes matching '{process}': it "
                                "does not exist, was never launched, or printed nothing") \
                    from None
        return success

