"""rmw_qos_profile_check_compatible's rules: a publisher's offer against a subscription's
request, as (level, reason), the level QoSCompatibility's value (rclpy.qos makes it one). The
rules name the policies as rmw does, so that this module stands below rclpy.qos."""

from __future__ import annotations

from typing import Any

OK, WARNING, ERROR = range(3)  # QoSCompatibility's values
_OPEN = ("SYSTEM_DEFAULT", "UNKNOWN", "BEST_AVAILABLE")


def check(pub: Any, sub: Any) -> tuple[int, str]:
    """Errors first (they decide), then warnings; OK with an empty reason."""
    errors, warnings = [], []
    if _is(pub.reliability, "BEST_EFFORT") and _is(sub.reliability, "RELIABLE"):
        errors.append("Best effort publisher and reliable subscription;")
    if _is(pub.durability, "VOLATILE") and _is(sub.durability, "TRANSIENT_LOCAL"):
        errors.append("Volatile publisher and transient local subscription;")
    errors += _durations("deadline", pub.deadline, sub.deadline)
    if _is(pub.liveliness, "AUTOMATIC") and _is(sub.liveliness, "MANUAL_BY_TOPIC"):
        errors.append("Publisher's liveliness is automatic and subscription's is manual by "
                      "topic;")
    errors += _durations("liveliness lease duration", pub.liveliness_lease_duration,
                         sub.liveliness_lease_duration)
    for policy, strict in (("reliability", "RELIABLE"), ("durability", "TRANSIENT_LOCAL"),
                           ("liveliness", "MANUAL_BY_TOPIC")):
        offered, requested = getattr(pub, policy), getattr(sub, policy)
        if offered.name in _OPEN and _is(requested, strict):
            warnings.append(f"Publisher {policy} is {offered.name} and subscription is "
                            f"{requested.name};")
    if errors:
        return ERROR, " ".join(f"ERROR: {e}" for e in errors)
    if warnings:
        return WARNING, " ".join(f"WARNING: {w}" for w in warnings)
    return OK, ""


def _is(policy: Any, name: str) -> bool:
    """Whether a policy (a member of one of rclpy.qos's policy enums) is the one named."""
    return policy.name == name


def _durations(what: str, offered: Any, requested: Any) -> list[str]:
    """A period the subscription asks for that the publisher does not promise (0 is none)."""
    if not requested.nanoseconds:
        return []
    if not offered.nanoseconds:
        return [f"Subscription has a {what}, but publisher does not;"]
    if offered.nanoseconds > requested.nanoseconds:
        return [f"Subscription {what} is less than publisher {what};"]
    return []
