"""rclpy.event_handler: middleware events of publishers and subscriptions. Of the events,
launcher raises the matched ones (rclpy/matched.py), through the PublisherEventCallbacks and
SubscriptionEventCallbacks given to create_publisher and create_subscription; deadlines,
liveliness, lost messages and incompatible QoS or types are not events on its bus, so those
callbacks are kept and never called."""

from __future__ import annotations

import warnings
from enum import IntEnum
from typing import Any

from launcher.records import dataclass
from rclpy.callback_groups import CallbackGroup  # noqa: F401 - as rclpy's module offers it
from rclpy.exceptions import RCLError
from rclpy.logging import get_logger  # noqa: F401
from rclpy.matched import (  # noqa: F401 - QoS…MatchedInfo as rclpy's module offers them
    QoSPublisherMatchedInfo,
    QoSSubscriptionMatchedInfo,
    StatusCounts,
)
from rclpy.qos import qos_policy_name_from_kind  # noqa: F401
from rclpy.waitable import NumberOfEntities, Waitable


class QoSPublisherEventType(IntEnum):
    """rcl's publisher event types."""

    RCL_PUBLISHER_OFFERED_DEADLINE_MISSED = 0
    RCL_PUBLISHER_LIVELINESS_LOST = 1
    RCL_PUBLISHER_OFFERED_INCOMPATIBLE_QOS = 2
    RCL_PUBLISHER_INCOMPATIBLE_TYPE = 3
    RCL_PUBLISHER_MATCHED = 4


class QoSSubscriptionEventType(IntEnum):
    """rcl's subscription event types."""

    RCL_SUBSCRIPTION_REQUESTED_DEADLINE_MISSED = 0
    RCL_SUBSCRIPTION_LIVELINESS_CHANGED = 1
    RCL_SUBSCRIPTION_REQUESTED_INCOMPATIBLE_QOS = 2
    RCL_SUBSCRIPTION_MESSAGE_LOST = 3
    RCL_SUBSCRIPTION_INCOMPATIBLE_TYPE = 4
    RCL_SUBSCRIPTION_MATCHED = 5


class QoSRequestedDeadlineMissedInfo(StatusCounts):
    """Deadlines missed."""


QoSOfferedDeadlineMissedInfo = QoSRequestedDeadlineMissedInfo


@dataclass
class QoSLivelinessChangedInfo:
    alive_count: int = 0
    not_alive_count: int = 0
    alive_count_change: int = 0
    not_alive_count_change: int = 0


class QoSLivelinessLostInfo(StatusCounts):
    """Liveliness lost."""


class QoSMessageLostInfo(StatusCounts):
    """Messages lost."""


@dataclass
class QoSRequestedIncompatibleQoSInfo(StatusCounts):
    """Incompatible QoS met, and the last policy at fault."""
    last_policy_kind: int = 0


QoSOfferedIncompatibleQoSInfo = QoSRequestedIncompatibleQoSInfo


class IncompatibleTypeInfo(StatusCounts):
    """Incompatible types met."""


class UnsupportedEventTypeError(RCLError):
    """Raised when registering a callback for an event type that is not supported."""


class EventHandler(Waitable):
    """One event of a publisher or subscription. launcher makes none itself: its matched
    events come through the event callbacks, and the others are not events on its bus, so
    constructing one raises UnsupportedEventTypeError, as rcl does for an event its
    middleware does not have."""

    def __init__(self, *, callback_group: Any, callback: Any, event_type: IntEnum,
                 parent_impl: Any) -> None:
        raise UnsupportedEventTypeError(
            f"event {getattr(event_type, 'name', event_type)} is not supported by launcher's "
            "bus as a stand-alone handler (give matched callbacks to create_publisher or "
            "create_subscription)")

    def get_num_entities(self) -> NumberOfEntities:
        """One event."""
        return NumberOfEntities(num_events=1)


class QoSEventHandler(EventHandler):
    """EventHandler's deprecated name."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        warnings.warn("QoSEventHandler is deprecated, use EventHandler instead.",
                      DeprecationWarning, stacklevel=2)
        super().__init__(*args, **kwargs)




class SubscriptionEventCallbacks:
    """A subscription's event callbacks (only `matched` is ever called on launcher's bus)."""

    def __init__(self, *, deadline: Any = None, incompatible_qos: Any = None,
                 liveliness: Any = None, message_lost: Any = None,
                 incompatible_type: Any = None, matched: Any = None,
                 use_default_callbacks: bool = True) -> None:
        self.deadline, self.incompatible_qos, self.liveliness = deadline, incompatible_qos, \
            liveliness
        self.message_lost, self.incompatible_type, self.matched = message_lost, \
            incompatible_type, matched
        self.use_default_callbacks = use_default_callbacks


class PublisherEventCallbacks:
    """A publisher's event callbacks (only `matched` is ever called on launcher's bus)."""

    def __init__(self, *, deadline: Any = None, incompatible_qos: Any = None,
                 liveliness: Any = None, incompatible_type: Any = None, matched: Any = None,
                 use_default_callbacks: bool = True) -> None:
        self.deadline, self.incompatible_qos, self.liveliness = deadline, incompatible_qos, \
            liveliness
        self.incompatible_type, self.matched = incompatible_type, matched
        self.use_default_callbacks = use_default_callbacks
