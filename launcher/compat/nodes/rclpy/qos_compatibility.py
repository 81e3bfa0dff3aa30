"""rmw_qos_profile_check_compatible's rules: a publisher's offer against a subscription's
request, as (QoSCompatibility, reason)."""

from __future__ import annotations

from typing import Any

from rclpy.qos import DurabilityPolicy as Dur
from rclpy.qos import LivelinessPolicy as Live
from rclpy.qos import QoSCompatibility
from rclpy.qos import ReliabilityPolicy as Rel

_OPEN = ("SYSTEM_DEFAULT", "UNKNOWN", "BEST_AVAILABLE")


def check(pub: Any, sub: Any) -> tuple[QoSCompatibility, str]:
    """Errors first (they decide), then warnings; OK with an empty reason."""
    errors, warnings = [], []
    if pub.reliability == Rel.BEST_EFFORT and sub.reliability == Rel.RELIABLE:
        errors.append("Best effort publisher and reliable subscription;")
    if pub.durability == Dur.VOLATILE and sub.durability == Dur.TRANSIENT_LOCAL:
        errors.append("Volatile publisher and transient local subscription;")
    errors += _durations("deadline", pub.deadline, sub.deadline)
    if pub.liveliness == Live.AUTOMATIC and sub.liveliness == Live.MANUAL_BY_TOPIC:
        errors.append("Publisher's liveliness is automatic and subscription's is manual by "
                      "topic;")
    errors += _durations("liveliness lease duration", pub.liveliness_lease_duration,
                         sub.liveliness_lease_duration)
    for policy, strict in (("reliability", Rel.RELIABLE), ("durability", Dur.TRANSIENT_LOCAL),
                           ("liveliness", Live.MANUAL_BY_TOPIC)):
        offered, requested = getattr(pub, policy), getattr(sub, policy)
        if offered.name in _OPEN and requested == strict:
            warnings.append(f"Publisher {policy} is {offered.name} and subscription is "
                            f"{requested.name};")
    if errors:
        return QoSCompatibility.ERROR, " ".join(f"ERROR: {e}" for e in errors)
    if warnings:
        return QoSCompatibility.WARNING, " ".join(f"WARNING: {w}" for w in warnings)
    return QoSCompatibility.OK, ""


def _durations(what: str, offered: Any, requested: Any) -> list[str]:
    """A period the subscription asks for that the publisher does not promise (0 is none)."""
    if not requested.nanoseconds:
        return []
    if not offered.nanoseconds:
        return [f"Subscription has a {what}, but publisher does not;"]
    if offered.nanoseconds > requested.nanoseconds:
        return [f"Subscription {what} is less than publisher {what};"]
    return []
