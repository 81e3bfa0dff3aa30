"""One exception root for every user-facing failure, and the place it points to."""

from __future__ import annotations

from collections.abc import Iterable
from typing import NamedTuple


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


class SubstitutionError(LaunchError):
    """A substitution could not be performed."""


class ExecutionError(LaunchError):
    """An action could not be carried out (a missing executable, a bad cwd, …)."""


class UsageError(LaunchError):
    """The command line was wrong."""


def did_you_mean(word: str, choices: Iterable[str]) -> str:
    """' (did you mean 'x'?)' when a close match exists, else ''."""
    import difflib  # only when reporting an error: start-up time

    close = difflib.get_close_matches(word, sorted(set(choices)), n=3, cutoff=0.6)
    if not close:
        return ""
    return " (did you mean " + " or ".join(f"'{c}'" for c in close) + "?)"
