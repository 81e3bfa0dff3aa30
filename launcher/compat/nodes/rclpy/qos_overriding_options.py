"""rclpy.qos_overriding_options: QoS policies a publisher or subscription takes from read-only
parameters, `qos_overrides.<topic>.<publisher|subscription>[_<id>].<policy>`, declared when
the entity is made with `qos_overriding_options=`; a parameter override (`-p`, a params file)
sets the policy."""

from __future__ import annotations

import copy
from collections.abc import Callable, Iterable
from typing import Any

from rcl_interfaces.msg import ParameterDescriptor, SetParametersResult

from rclpy import qos as qos_module
from rclpy.duration import Duration
from rclpy.exceptions import ParameterAlreadyDeclaredException
from rclpy.properties import readonly
from rclpy.qos import QoSPolicyKind, QoSProfile

__all__ = ["InvalidQosOverridesError", "QoSOverridingOptions", "QosCallbackResult",
           "QosCallbackType", "declare_qos_parameters"]

QosCallbackResult = SetParametersResult
QosCallbackType = Callable[[QoSProfile], QosCallbackResult]
ENUMS = {QoSPolicyKind.HISTORY: qos_module.HistoryPolicy,
         QoSPolicyKind.RELIABILITY: qos_module.ReliabilityPolicy,
         QoSPolicyKind.DURABILITY: qos_module.DurabilityPolicy,
         QoSPolicyKind.LIVELINESS: qos_module.LivelinessPolicy}
DURATIONS = (QoSPolicyKind.LIFESPAN, QoSPolicyKind.DEADLINE,
             QoSPolicyKind.LIVELINESS_LEASE_DURATION)


class InvalidQosOverridesError(Exception):
    """The options' callback refused the QoS the overrides made."""


class QoSOverridingOptions:
    """Which policies have a parameter (`policy_kinds`), a `callback(qos)` that validates the
    result, and an `entity_id` that tells apart two entities on one topic."""

    def __init__(self, policy_kinds: Iterable[QoSPolicyKind], *,
                 callback: QosCallbackType | None = None, entity_id: str | None = None) -> None:
        self._policy_kinds = policy_kinds
        self._callback = callback
        self._entity_id = entity_id

    policy_kinds = readonly("_policy_kinds", "The policies that get a parameter.")
    callback = readonly("_callback", "The validating callback, if any.")
    entity_id = readonly("_entity_id", "The entity's id, if any.")

    @classmethod
    def with_default_policies(cls, *, callback: QosCallbackType | None = None,
                              entity_id: str | None = None) -> QoSOverridingOptions:
        """Options for history, depth and reliability."""
        return cls((QoSPolicyKind.HISTORY, QoSPolicyKind.DEPTH, QoSPolicyKind.RELIABILITY),
                   callback=callback, entity_id=entity_id)


def declare_qos_parameters(kind: str, node: Any, topic_name: str, qos: QoSProfile,
                           options: QoSOverridingOptions) -> QoSProfile:
    """The QoS of a `kind` ("publisher" or "subscription") entity on the resolved
    `topic_name`: `qos` with each policy the options name taken from its parameter (declared
    now, with the policy's value in `qos` as default)."""
    qos = copy.copy(qos)
    suffix = "" if options.entity_id is None else f"_{options.entity_id}"
    prefix = f"qos_overrides.{topic_name}.{kind}{suffix}."
    about = f"for {kind} `{topic_name}` with id `{options.entity_id}`"
    for policy in options.policy_kinds:
        if policy in (QoSPolicyKind.INVALID, QoSPolicyKind.AVOID_ROS_NAMESPACE_CONVENTIONS) or \
                kind == "subscription" and policy == QoSPolicyKind.LIFESPAN:
            continue
        name = prefix + policy.name.lower()
        descriptor = ParameterDescriptor(description=f"{policy.name.lower()} {about}",
                                         read_only=True)
        try:
            value = node.declare_parameter(name, _as_parameter(qos, policy), descriptor).value
        except ParameterAlreadyDeclaredException:
            value = node.get_parameter(name).value
        setattr(qos, policy.name.lower(), _as_policy(policy, value))
    if options.callback is not None:
        result = options.callback(qos)
        if not result.successful:
            raise InvalidQosOverridesError(f"Provided QoS overrides {about}, are not valid: "
                                           f"{result.reason}")
    return qos


def _as_parameter(qos: QoSProfile, policy: QoSPolicyKind) -> str | int | bool:
    value = getattr(qos, policy.name.lower())
    if policy in ENUMS:
        if value.name == "UNKNOWN":
            raise ValueError("User provided QoS profile is invalid")
        return value.name.lower()
    return value.nanoseconds if isinstance(value, Duration) else value


def _as_policy(policy: QoSPolicyKind, value: Any) -> Any:
    if policy in ENUMS:
        try:
            return ENUMS[policy][str(value).upper()]
        except KeyError:
            raise RuntimeError(f"Unexpected QoS override for policy `{policy.name.lower()}`: "
                               f"`{value}`") from None
    return Duration(nanoseconds=value) if policy in DURATIONS else value


from launcher.compat.finder import rest_from_layout  # noqa: E402 - the rest of the real module's names

__getattr__ = rest_from_layout(__name__)
