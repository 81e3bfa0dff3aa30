"""rclpy.type_support: the typing protocols of message, service and action classes, and the
checks that a class is one (launcher's interface classes carry their type's name in _TYPE,
where rosidl's carry a compiled type support)."""

from __future__ import annotations

from typing import Any, Protocol

from launcher.compat import rosidl
from rclpy.exceptions import NoTypeSupportImportedException


class PyCapsule(Protocol):
    """The type of rosidl's compiled type support handles."""


class CommonMsgSrvMetaClass(type(Protocol)):  # type: ignore[misc]
    """What messages and services share."""


class MsgMetaClass(CommonMsgSrvMetaClass):
    """The metaclass of a message alias."""


class Msg(Protocol, metaclass=MsgMetaClass):
    """Any message class."""


class Srv(Protocol, metaclass=CommonMsgSrvMetaClass):
    """Any service class (with Request, Response and Event)."""


class Action(Protocol, metaclass=CommonMsgSrvMetaClass):
    """Any action class (with Goal, Result, Feedback and its hidden services)."""


class EventMessage(Msg, Protocol):
    """A service's event message."""


class FeedbackMessage(Msg, Protocol):
    """An action's feedback message (goal id and feedback)."""


class SendGoalServiceRequest(Msg, Protocol):
    """An action's send-goal request."""


class SendGoalServiceResponse(Msg, Protocol):
    """An action's send-goal response."""


class SendGoalService(Protocol):
    """An action's send-goal service."""


class GetResultServiceRequest(Msg, Protocol):
    """An action's get-result request."""


class GetResultServiceResponse(Msg, Protocol):
    """An action's get-result response."""


class GetResultService(Protocol):
    """An action's get-result service."""


def check_for_type_support(msg_or_srv_type: Any) -> None:
    """NoTypeSupportImportedException unless `msg_or_srv_type` is an interface class
    (AttributeError, with rclpy's hint, for a class that is none at all)."""
    if isinstance(msg_or_srv_type, str) or not hasattr(msg_or_srv_type, "_TYPE"):
        raise AttributeError(f"{msg_or_srv_type!r} has no type support. This might be a ROS 1 "
                             "message type but it should be a ROS 2 message type. Make sure "
                             "to source your ROS 2 workspace after your ROS 1 workspace.")
    try:
        rosidl.type_name_of(msg_or_srv_type)
    except TypeError:
        raise NoTypeSupportImportedException() from None


def check_is_valid_msg_type(msg_type: Any) -> None:
    """RuntimeError unless `msg_type` is a message class (not a service or action)."""
    check_for_type_support(msg_type)
    if hasattr(msg_type, "Request") or hasattr(msg_type, "Goal"):
        raise RuntimeError(f"The message type provided is not valid ({msg_type}), this might "
                           "be a service or action")


def check_is_valid_srv_type(srv_type: Any) -> None:
    """RuntimeError unless `srv_type` is a service class (with Request and Response)."""
    check_for_type_support(srv_type)
    if getattr(srv_type, "Request", None) is None or getattr(srv_type, "Response", None) is None:
        raise RuntimeError(f"The service type provided is not valid ({srv_type}), this might "
                           "be a message or action")
