"""`$(command 'CMD' [fail|warn|ignore|capture])`: the standard output of a command.

As in ROS 2 the output is returned exactly, trailing newline included (robot descriptions and
most values do not mind; strip it with `$(eval)` where it matters). A non-zero exit always
fails and shows the command's stderr; the second argument decides what stderr on success
does: `fail` (the default) fails, `warn` logs it, `ignore` drops it, `capture` appends it to
the output. The command is split like a shell command line but never run by a shell.
`xacro` calls run in-process when that gives the same result (see packages.xacro).
"""

from __future__ import annotations

import shlex
import subprocess
from dataclasses import dataclass

from launcher.description.substitution import Substitution, Text_, perform_text, substitution
from launcher.errors import LaunchError
from launcher.packages.xacro import run_xacro, runs_in_process
from launcher.runtime.context import LaunchContext

_MODES = ("fail", "warn", "ignore", "capture")


@substitution("command")
@dataclass(frozen=True)
class Command(Substitution):
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
        if result.returncode != 0:
            stderr = (result.stderr or "").strip()
            detail = f"; its stderr:\n{stderr}" if stderr else " (no stderr output)"
            raise self.fail(f"command '{text}' failed with exit code {result.returncode}{detail}")
        if result.stderr and mode == "fail":
            raise self.fail(f"command '{text}' wrote to stderr (use $(command '…' warn) or "
                            f"ignore to allow it):\n{result.stderr.strip()}")
        if result.stderr and mode == "warn":
            context.log("WARN", f"command '{text}' wrote to stderr:\n{result.stderr.strip()}")
        return result.stdout


def _run(argv: list[str], mode: str, context: LaunchContext) -> subprocess.CompletedProcess:
    stderr = subprocess.STDOUT if mode == "capture" else subprocess.PIPE
    return subprocess.run(argv, stdout=subprocess.PIPE, stderr=stderr, text=True,
                          env=context.environment, stdin=subprocess.DEVNULL, check=False)
