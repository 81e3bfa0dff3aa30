"""launch_testing.tools.process: starting a process from an active test (launch_process) and
what the test sees of it (ProcessProxy)."""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Iterator
from typing import Any


class ProcessProxy:
    """One process of a test, as the active tests see it: its output and its state."""

    def __init__(self, process_action: Any, proc_info: Any, proc_output: Any, *,
                 output_filter: Callable[[str], str] | None = None) -> None:
        if output_filter is not None and not callable(output_filter):
            raise TypeError(f"Expected 'output_filter' to be callable but got "
                            f"'{output_filter!r}'")
        self.target_process_action = process_action
        self._info, self._output, self._filter = proc_info, proc_output, output_filter

    def _text(self, stream: str | None) -> str:
        try:
            outputs = self._output[self.target_process_action]
        except KeyError:
            return ""
        text = "".join(o.text.decode(errors="replace") for o in outputs
                       if stream is None or o.stream == stream)
        return self._filter(text) if self._filter is not None else text

    @property
    def stdout(self) -> str:
        return self._text("stdout")

    @property
    def stderr(self) -> str:
        return self._text("stderr")

    @property
    def output(self) -> str:
        return self._text(None)

    @property
    def running(self) -> bool:
        known = self.target_process_action in self._info.processes()
        return known and not self._info[self.target_process_action].exited

    @property
    def terminated(self) -> bool:
        known = self.target_process_action in self._info.processes()
        return known and self._info[self.target_process_action].exited

    @property
    def exit_code(self) -> int | None:
        return self._info[self.target_process_action].returncode

    def wait_for_shutdown(self, timeout: float | None = None) -> bool:
        """Wait until the process has exited (up to `timeout` seconds); whether it did."""
        with self._info.proc_event:
            return self._info.proc_event.wait_for(lambda: self.terminated, timeout=timeout)

    def wait_for_output(self, condition: Callable[[str], bool] | None = None,
                        timeout: float | None = None) -> bool:
        """Wait until the output so far satisfies `condition` (any output when None)."""
        wanted = condition or (lambda output: True)
        with self._output.io_event:
            return self._output.io_event.wait_for(
                lambda: self.running and wanted(self.output), timeout=timeout)


@contextlib.contextmanager
def launch_process(launch_service: Any, process_action: Any, proc_info: Any, proc_output: Any,
                   **kwargs: Any) -> Iterator[ProcessProxy]:
    """Start `process_action` in the running launch and give its proxy; on leaving, stop it
    unless it has ended."""
    launch_service.start_action(process_action)
    proxy = ProcessProxy(process_action, proc_info, proc_output, **kwargs)
    try:
        yield proxy
    finally:
        if not proxy.terminated:
            launch_service.stop_action(process_action)
