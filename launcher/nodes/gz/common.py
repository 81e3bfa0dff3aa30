"""What the `gz` verbs share: Gazebo's type names and name listings."""

from __future__ import annotations

from typing import Any

from launcher.bus.session import open_session
from launcher.errors import LaunchError, UsageError, did_you_mean
from launcher.nodes.conversions import SIM_MESSAGES, gz_short_name, sim_type


def gz_name(type_name: str) -> str:
    short = type_name.rsplit("/", 1)[-1]
    return "gz.msgs.Pose_V" if short == "PoseV" else f"gz.msgs.{short}"


def print_names(collect: Any) -> int:
    """Print the names `collect(session)` finds on the bus, sorted."""
    session = open_session("client")
    try:
        names = collect(session)
    finally:
        session.close()
    for name in sorted(names):
        print(name)
    return 0


def message_type(gz_type: str) -> tuple[str, str]:
    """(the sim's type, Gazebo's short name) for `gz.msgs.NAME`."""
    short = gz_short_name(gz_type)
    if not short:
        raise UsageError(f"unknown message type '{gz_type}': expected gz.msgs.NAME"
                         f"{did_you_mean(gz_type, [f'gz.msgs.{m}' for m in SIM_MESSAGES])}")
    try:
        return sim_type(gz_type), short
    except LaunchError as exc:
        raise UsageError(exc.message) from None


