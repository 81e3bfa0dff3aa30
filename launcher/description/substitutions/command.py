"""`$(command 'CMD' [fail|warn|ignore|capture])`: the standard output of a command.

As in ROS 2 the output is returned exactly, trailing newline included (robot descriptions and
most values do not mind; strip it with `$(eval)` where it matters). A non-zero exit always
fails and shows the command's stderr; the second argument decides what stderr on success
does: `fail` (the default) fails, `warn` logs it, `ignore` drops it, `capture` appends it to
the output. The command is split like a shell command line but never run by a shell.
`xacro` calls run in-process when that gives the same result (see packages.xacro). The
command runs in a session of its own: Ctrl-C stops it (and all it started) at once, and the
launch's watchdog ends it if the launcher is killed.
"""

from __future__ import annotations

import shlex

from launcher.description.substitution import Substitution, Text_, perform_text, substitution
from launcher.errors import LaunchError
from launcher.lineage import run_to_end
from launcher.packages.xacro import run_xacro, runs_in_process
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext

_MODES = ("fail", "warn", "ignore", "capture")


@substitution("command")
@dataclass(frozen=True)
class Command(Substitution):
    """The standard output of a command, exactly (its trailing newline too); a non-zero exit
    fails with its stderr. ON_STDERR (fail, warn, ignore, capture) says what output on stderr
    does when it succeeds."""

    command: Text_
    on_stderr: Text_ | None = None

    def perform(self, context: LaunchContext) -> str:
        text = perform_text(context, self.command)
        mode = "fail" if self.on_stderr is None else perform_text(context, self.on_stderr)
        if mode not in _MODES:
            raise self.fail(f"command: the second argument must be one of "
                            f"{', '.join(_MODES)}, got '{mode}'")
        try:
            argv = shlex.split(text)
        except ValueError as exc:
            raise self.fail(f"command: cannot split '{text}': {exc}") from None
        if not argv:
            raise self.fail("command: the command is empty")
        if runs_in_process(argv, context.environment):
            try:
                output = run_xacro(argv, context.packages)
            except LaunchError as exc:
                raise exc.at(self.where) from None
            if output is not None:
                return output
        try:
            result = _run(argv, mode, context)
        except FileNotFoundError:
            raise self.fail(f"command: no executable '{argv[0]}' (command: {text})") from None
        except PermissionError:
            raise self.fail(f"command: '{argv[0]}' is not executable (command: {text})") from None
        code, stdout, stderr = result
        if code != 0:
            detail = f"; its stderr:\n{stderr.strip()}" if stderr.strip() else \
                " (no stderr output)"
            raise self.fail(f"command '{text}' failed with exit code {code}{detail}")
        if stderr and mode == "fail":
            raise self.fail(f"command '{text}' wrote to stderr (use $(command '…' warn) or "
                            f"ignore to allow it):\n{stderr.strip()}")
        if stderr and mode == "warn":
            context.log("WARN", f"command '{text}' wrote to stderr:\n{stderr.strip()}")
        return stdout


def _run(argv: list[str], mode: str, context: LaunchContext) -> tuple[int, str, str]:
    """(exit status, stdout, stderr): in a session of its own, stopped whole on Ctrl-C, and
    nothing it started in its group left running (lineage.run_to_end)."""
    code, out, err = run_to_end(argv, context.environment, merge_stderr=mode == "capture")
    return code, _text(out), _text(err)


def _text(data: bytes) -> str:
    """Decoded with universal newlines, as ROS 2 reads a command's output."""
    return data.decode(errors="replace").replace("\r\n", "\n").replace("\r", "\n")
