"""colcon's `.dsv` hooks: one `TYPE;ARGS…` line each, applied to an environment.

    prepend-non-duplicate;NAME;V1[;V2…]            prepend each value unless already present
    prepend-non-duplicate-if-exists;NAME;V1[;V2…]   the same, skipping paths that do not exist
    append-non-duplicate;NAME;V1[;V2…]             append each value unless already present
    set;NAME;VALUE                                 prefix/VALUE if that exists, else VALUE
    set-if-unset;NAME;VALUE                        the same, only if NAME is unset or empty
    source;PATH                                    another hook (a .dsv twin wins over .sh)

Values: empty means the prefix, relative means prefix/value, absolute stays. A duplicate is
skipped, not moved; several values are taken in order, so with prepend the last ends up first.
Blank lines and `#` comments are skipped.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from pathlib import Path

from launcher.errors import Location, ParseError, did_you_mean
from launcher.records import dataclass, field

TYPES = {"prepend-non-duplicate": 2, "prepend-non-duplicate-if-exists": 2,
         "append-non-duplicate": 2, "set": 2, "set-if-unset": 2, "source": 1}


@dataclass
class HookEnvironment:
    """The environment being built, and what was unset when hooks began (for the final strip)."""

    values: dict[str, str]
    unset_at_start: set[str] = field(default_factory=set)
    # Maps a value before it is stored (link-prefix paths -> the package's real folder).
    real: Callable[[str], str] = field(default=lambda value: value)

    def note(self, name: str) -> None:
        if not self.values.get(name):
            self.unset_at_start.add(name)

    def finish(self) -> dict[str, str]:
        for name in self.unset_at_start:
            if name in self.values:
                self.values[name] = self.values[name].strip(os.pathsep)
        return self.values


def resolve_value(value: str, prefix: Path) -> str:
    if not value:
        return str(prefix)
    return value if os.path.isabs(value) else str(prefix / value)


def apply_dsv(path: Path, text: str, prefix: Path, env: HookEnvironment,
              source: Callable[[Path, Location], None]) -> None:
    """Apply the lines of one .dsv file; `source` runs hooks named by `source;` lines."""
    for number, raw in enumerate(text.splitlines(), 1):
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        where = Location(str(path), number, 1)
        if ";" not in line:
            raise ParseError(f"expected TYPE;ARGUMENTS, got '{line}'", where)
        kind, *args = line.split(";")
        if kind not in TYPES:
            raise ParseError(f"unknown type '{kind}'{did_you_mean(kind, TYPES)}; expected one "
                             f"of {', '.join(TYPES)}", where)
        if len(args) < TYPES[kind] or (kind != "source" and not args[0]):
            usage = "source;PATH" if kind == "source" else f"{kind};NAME;VALUE"
            raise ParseError(f"too few arguments for '{kind}': expected {usage}", where)
        if kind == "source":
            source(Path(resolve_value(args[0], prefix)), where)
        elif kind.startswith("set"):
            _set(env, args[0], ";".join(args[1:]), prefix, only_if_unset=kind == "set-if-unset")
        else:
            _add(env, args[0], args[1:], prefix, append=kind.startswith("append"),
                 must_exist=kind.endswith("-if-exists"))


def _set(env: HookEnvironment, name: str, value: str, prefix: Path, only_if_unset: bool) -> None:
    env.note(name)
    if only_if_unset and env.values.get(name):
        return
    candidate = prefix / value if value and not os.path.isabs(value) else None
    if not value:
        env.values[name] = env.real(str(prefix))
    elif candidate is not None and candidate.exists():
        env.values[name] = env.real(str(candidate))
    else:
        env.values[name] = value


def _add(env: HookEnvironment, name: str, values: list[str], prefix: Path, append: bool,
         must_exist: bool) -> None:
    env.note(name)
    for raw in values:
        value = env.real(resolve_value(raw, prefix))
        if must_exist and not os.path.exists(value):
            continue
        current = env.values.get(name, "")
        parts = current.split(os.pathsep) if current else []
        if value in parts:
            continue  # present already: skipped, not moved
        env.values[name] = os.pathsep.join([*parts, value] if append else [value, *parts])
