"""rospy.impl.registration: who is told when the node declares or drops a publisher,
subscriber or service (launcher's rospy tells them; its bus announces the node on the
graph itself), and the topic and service managers' holders."""

from __future__ import annotations

import threading
import traceback
from typing import Any

from rospy.core import (  # noqa: F401 (rospy.impl.registration has them)
    add_preshutdown_hook,
    is_shutdown,
    is_shutdown_requested,
    logdebug,
    logerr,
    logfatal,
    loginfo,
    logwarn,
    signal_shutdown,
    xmlrpcapi,
)
from rospy.names import get_caller_id, get_namespace  # noqa: F401

_managers: dict[str, Any] = {"topic": None, "service": None}


def set_topic_manager(tm: Any) -> None:
    _managers["topic"] = tm


def get_topic_manager() -> Any:
    """The topic manager set_topic_manager gave (launcher's rospy keeps none: None)."""
    return _managers["topic"]


def set_service_manager(sm: Any) -> None:
    _managers["service"] = sm


def get_service_manager() -> Any:
    """The service manager set_service_manager gave (launcher's rospy keeps none: None)."""
    return _managers["service"]


class Registration:
    """The kinds of declaration."""

    PUB = "pub"
    SUB = "sub"
    SRV = "srv"


class RegistrationListener:
    """What is told of the node's declarations: override reg_added and reg_removed."""

    def reg_added(self, resolved_name: str, data_type_or_uri: str, reg_type: str) -> None:
        """A publisher, subscriber or service was declared (`reg_type`: a Registration)."""

    def reg_removed(self, resolved_name: str, data_type_or_uri: str, reg_type: str) -> None:
        """A publisher, subscriber or service was dropped."""


class RegistrationListeners:
    """The listeners, told in the order they were added."""

    def __init__(self) -> None:
        self.listeners: list[RegistrationListener] = []
        self.lock = threading.Lock()

    def add_listener(self, l: RegistrationListener) -> None:  # noqa: E741 (rospy's name)
        if not isinstance(l, RegistrationListener):
            raise TypeError(f"{l!r} is not a RegistrationListener")
        with self.lock:
            self.listeners.append(l)

    def notify_removed(self, resolved_name: str, data_type_or_uri: str,
                       reg_type: str) -> None:
        self._notify("reg_removed", resolved_name, data_type_or_uri, reg_type)

    def notify_added(self, resolved_name: str, data_type: str, reg_type: str) -> None:
        self._notify("reg_added", resolved_name, data_type, reg_type)

    def _notify(self, method: str, *args: str) -> None:
        with self.lock:
            listeners = list(self.listeners)
        for listener in listeners:
            try:
                getattr(listener, method)(*args)
            except Exception:  # one listener's error does not stop the others
                logerr(traceback.format_exc())

    def clear(self) -> None:
        """Remove every listener."""
        with self.lock:
            self.listeners.clear()


_registration_listeners = RegistrationListeners()


def get_registration_listeners() -> RegistrationListeners:
    return _registration_listeners
