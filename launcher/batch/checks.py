"""The batch file against what its job files declare (read by `launcher.cli.batch_inspect`):
every matrix key and fixed argument must be a launch argument of the job it is given to."""

from __future__ import annotations

from typing import Any

from launcher.batch.matrix import Overrides, entry_matrix
from launcher.batch.spec import BatchFile, Entry
from launcher.errors import LaunchError, Location, ParseError, did_you_mean


def check_entries(batch: BatchFile, overrides: Overrides,
                  facts: list[dict[str, Any]]) -> list[str]:
    """Raise at the first key that is no argument of its job; the warnings where a file's
    arguments could not all be listed."""
    warnings = []
    for entry, fact in zip(batch.jobs, facts, strict=True):
        if "error" in fact:
            raise LaunchError(f"{fact['error']}\n  (job at {entry.where})")
        keys = [*entry_matrix(batch, entry, overrides), *entry.arguments, *overrides.fixed]
        for key in dict.fromkeys(keys):
            if key in fact["arguments"]:
                continue
            where = _place(batch, entry, key)
            if not fact["complete"]:
                warnings.append(f"{where or 'the command line'}: '{key}' is not among the "
                                f"arguments launcher could list for {entry.file}; "
                                f"{'; '.join(fact['unresolved'])}")
                continue
            takes = ", ".join(sorted(fact["arguments"])) or "none"
            raise ParseError(f"'{key}' is not a launch argument of {entry.file}"
                             f"{did_you_mean(key, fact['arguments'])}; it takes: {takes}",
                             where)
    return warnings


def _place(batch: BatchFile, entry: Entry, key: str) -> Location | None:
    for places in (entry.places, batch.places):
        for kind in ("matrix", "arguments"):
            if f"{kind}.{key}" in places:
                return places[f"{kind}.{key}"]
    return None
