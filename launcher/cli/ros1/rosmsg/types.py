"""The message or service types rosmsg and rossrv list."""

from __future__ import annotations


def types_of(kind: str) -> list[str]:
    """Every type of `kind` ('msg' or 'srv'), as `pkg/kind/Name`."""
    from launcher.cli.interface.types import all_types

    return all_types()[kind]
