"""One exception root for every user-facing failure, the place it points to, and the one
reporter every entry point (the CLI, `launcher sim`, each built-in node) prints it with."""

from __future__ import annotations

import os
import sys
from collections.abc import Callable, Iterable
from typing import NamedTuple

DEBUG_VARIABLE = "LAUNCHER_DEBUG"  # "1": tracebacks too (`launcher launch --debug` sets it)


class Location(NamedTuple):
    """A place in a user's file: 1-based line and column; either may be unknown (0)."""

    file: str
    line: int = 0
    column: int = 0

    def shifted(self, columns: int) -> Location:
        return Location(self.file, self.line, self.column + columns) if self.column else self

    def __str__(self) -> str:
        parts = [self.file]
        if self.line:
            parts.append(str(self.line))
            if self.column:
                parts.append(str(self.column))
        return ":".join(parts)


class LaunchError(Exception):
    """A failure the user can act on. `main()` prints it as one line; `--debug` adds the trace."""

    exit_code = 1

    def __init__(self, message: str, location: Location | None = None) -> None:
        super().__init__(message)
        self.message = message
        self.location = location

    def at(self, location: Location | None) -> LaunchError:
        """Attach a location if this error has none yet (the innermost place wins)."""
        if self.location is None and location is not None:
            self.location = location
        return self

    def __str__(self) -> str:
        return f"{self.location}: {self.message}" if self.location else self.message


class ParseError(LaunchError):
    """The launch file (or a config file) is not valid."""


class SubstitutionFailure(RuntimeError):
    """launch.substitutions.SubstitutionFailure: a substitution could not be performed (what
    code of the user's catches; launcher's own failures are SubstitutionErrors, one kind of
    it)."""


class SubstitutionError(LaunchError, SubstitutionFailure):
    """A substitution could not be performed."""


class ExecutionError(LaunchError):
    """An action could not be carried out (a missing executable, a bad cwd, …)."""


class ParameterError(LaunchError):
    """A node's parameter holds a value its declaration refuses. `message` names the
    parameter ("parameter 'rate': expected …"); the error names its node before it."""

    def __init__(self, name: str, message: str, node: str = "") -> None:
        super().__init__(f"{node}: {message}" if node else message)
        self.name, self.node = name, node


class UsageError(LaunchError):
    """The command line was wrong (exit status 2, as argparse's own errors)."""

    exit_code = 2


class Interrupted(KeyboardInterrupt):
    """SIGINT or SIGTERM, raised where the launcher was busy (loading, evaluating, waiting on
    a `$(command)`); the exit status is 128 + the signal's number, as a shell reports it."""

    def __init__(self, signum: int = 2) -> None:
        super().__init__(signum)
        self.signum = signum


def did_you_mean(word: str, choices: Iterable[str]) -> str:
    """' (did you mean 'x'?)' when a close match exists, else ''."""
    import difflib  # only when reporting an error: start-up time

    close = difflib.get_close_matches(word, sorted(set(choices)), n=3, cutoff=0.6)
    if not close:
        return ""
    return " (did you mean " + " or ".join(f"'{c}'" for c in close) + "?)"


def interrupt_behind(exc: BaseException) -> BaseException | None:
    """The KeyboardInterrupt (Ctrl-C, SIGTERM) this exception is, or arose while handling: a
    library's cleanup that fails because a signal cut its `try` short (argparse restores
    attributes it never saved) is the signal's doing. An error raised `from None` in place of
    one (a launch file's own KeyboardInterrupt, reported as its error) is not."""
    current: BaseException | None = exc
    for _ in range(100):
        if current is None or isinstance(current, KeyboardInterrupt):
            return current
        current = current.__cause__ or (None if current.__suppress_context__ else
                                        current.__context__)
    return None


def report(exc: BaseException, label: str = "", debug: bool = False) -> int:
    """Print a failure as one line on stderr (with its traceback when debugging); the exit
    status it means: the LaunchError's own, 130 for Ctrl-C, 1 for anything else."""
    behind = interrupt_behind(exc)  # a failure in cleanup a signal interrupted: the signal's
    if behind is not None:
        return 128 + getattr(behind, "signum", 2)
    if debug or os.environ.get(DEBUG_VARIABLE) == "1":
        import traceback  # only when debugging: start-up time

        traceback.print_exception(exc)
    prefix = f"[{label}] " if label and not _names(exc, label) else ""
    if isinstance(exc, LaunchError):
        print(f"{prefix}error: {exc}", file=sys.stderr, flush=True)
        return exc.exit_code
    print(f"{prefix}error: internal error: {type(exc).__name__}: {exc} (run with --debug for "
          "the traceback)", file=sys.stderr, flush=True)
    return 1


def _names(exc: BaseException, label: str) -> bool:
    """Whether the error names who says it already: a node's parameter error names its node,
    which a built-in node's label names too (said once, not twice)."""
    return isinstance(exc, ParameterError) and exc.node.strip("/") == label


def reported(run: Callable[[], int | None], label: str = "", debug: bool = False) -> int:
    """`run()`'s exit status; whatever it raises goes through `report`."""
    try:
        return int(run() or 0)
    except BrokenPipeError:  # `launcher topic echo … | head`: the reader is done, so are we
        import os

        with open(os.devnull, "w") as devnull:  # nothing more reaches the closed pipe
            os.dup2(devnull.fileno(), sys.stdout.fileno())
        return 0
    except (Exception, KeyboardInterrupt) as exc:
        return report(exc, label, debug)
