"""launch_testing.asserts: a test's checks of exit codes and output."""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from typing import Any

from launcher.compat.testing.tools.output import remove_ansi_escape_sequences
from launcher.compat.testing.tools.text import build_text_match
from launcher.compat.testing.util import resolveProcesses

EXIT_OK, EXIT_FORCED = 0, 1
EXIT_SIGINT, EXIT_SIGQUIT, EXIT_SIGKILL, EXIT_SIGSEGV = 130, 131, 137, 139


def assertExitCodes(proc_info: Any, allowable_exit_codes: Sequence[int] = (EXIT_OK,),  # noqa: N802
                    process: Any = None, cmd_args: Any = None, *,
                    strict_proc_matching: bool = True) -> None:
    """Each process `process` names (every process by default) exited with one of
    `allowable_exit_codes`."""
    for code in allowable_exit_codes:
        assert isinstance(code, int), f"Provided exit code {code} is not an int"
    for action in resolveProcesses(proc_info, process=process, cmd_args=cmd_args,
                                   strict_proc_matching=strict_proc_matching):
        info = proc_info[action]
        assert info.returncode in allowable_exit_codes, \
            f"Proc {info.process_name} exited with code {info.returncode}"


def assertInStream(proc_output: Any, expected_output: Any, process: Any,  # noqa: N802
                   cmd_args: Any = None, *, output_filter: Any = None,
                   strict_proc_matching: bool = True, strip_ansi_escape_sequences: bool = True,
                   stream: str = "stderr") -> None:
    """`expected_output` (a text, a regular expression, or a list of them in order) is in
    `stream` (stdout or stderr) of a process `process` names (any process when None)."""
    if stream not in ("stdout", "stderr"):
        raise ValueError("Invalid value for stream; must be 'stdout' or 'stderr'")
    if output_filter is not None and not callable(output_filter):
        raise ValueError("output_filter is not callable")
    matches = build_text_match(expected_output)
    actions = resolveProcesses(proc_output, process=process, cmd_args=cmd_args,
                               strict_proc_matching=strict_proc_matching)
    for action in actions:
        text = "".join(out.text.decode(errors="replace") for out in proc_output[action]
                       if out.stream == stream)
        if strip_ansi_escape_sequences:
            text = remove_ansi_escape_sequences(text)
        if output_filter is not None:
            text = output_filter(text)
        if matches(text) is not None:
            return
    names = ", ".join(sorted(proc_output[a][0].process_name for a in actions
                             if proc_output[a]))
    raise AssertionError(f"Did not find '{expected_output}' in output for any of the matching "
                         f"processes: {names}")


def assertInStdout(proc_output: Any, expected_output: Any, process: Any,  # noqa: N802
                   cmd_args: Any = None, **kwargs: Any) -> None:
    """assertInStream on standard output."""
    assertInStream(proc_output, expected_output, process, cmd_args, stream="stdout", **kwargs)


def assertInStderr(proc_output: Any, expected_output: Any, process: Any,  # noqa: N802
                   cmd_args: Any = None, **kwargs: Any) -> None:
    """assertInStream on standard error."""
    assertInStream(proc_output, expected_output, process, cmd_args, stream="stderr", **kwargs)


def assertDefaultStream() -> str:  # noqa: N802
    """The stream assertInStream looks at when none is given."""
    return "stderr"


class SequentialTextChecker:
    """Texts found in a process's output one after the other."""

    def __init__(self, output: list[str]) -> None:
        self._output = output
        self._index, self._offset = 0, 0

    def assertInText(self, msg: str) -> None:  # noqa: N802
        """Same as assertInStdout."""
        self.assertInStdout(msg)

    def assertInStdout(self, msg: str) -> None:  # noqa: N802
        """`msg` comes after the text found last."""
        offset = self._offset
        for index in range(self._index, len(self._output)):
            found = self._output[index].find(msg, offset)
            if found != -1:
                self._index, self._offset = index, found + len(msg)
                return
            offset = 0
        near = "".join(self._output[max(0, self._index - 2):self._index + 4])
        raise AssertionError(f"'{msg}' not found in sequence after previous match.  The "
                             f"output near the last matched line:\n{near}")


@contextmanager
def assertSequentialStdout(proc_output: Any, process: Any,  # noqa: N802
                           cmd_args: Any = None) -> Iterator[SequentialTextChecker]:
    """A checker whose assertInStdout calls must find their texts in the order given, in
    the standard output of the one process `process` names."""
    (action,) = resolveProcesses(proc_output, process=process, cmd_args=cmd_args,
                                 strict_proc_matching=True)
    yield SequentialTextChecker([out.text.decode(errors="replace")
                                 for out in proc_output[action] if out.stream == "stdout"])
