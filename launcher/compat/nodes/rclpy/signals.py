"""rclpy.signals: SIGINT and SIGTERM end spinning. The handler interrupts every context that
rclpy.init started and triggers the SignalHandlerGuardConditions, then hands the signal on to
the handler that was there before (Python's KeyboardInterrupt for SIGINT); a SIGTERM with no
handler before ends spinning with ExternalShutdownException, as rclpy's does."""

from __future__ import annotations

import signal
import threading
import weakref
from enum import IntEnum
from typing import Any

from rclpy.exceptions import (
    ExternalShutdownException,
    InvalidHandle,  # noqa: F401 - rclpy.signals offers it
)
from rclpy.guard_condition import GuardCondition


class SignalHandlerOptions(IntEnum):
    """Which signals rclpy handles."""

    NO = 0
    SIGINT = 1
    SIGTERM = 2
    ALL = 3


_contexts: weakref.WeakSet[Any] = weakref.WeakSet()  # what a signal interrupts
_guards: weakref.WeakSet[Any] = weakref.WeakSet()  # what a signal triggers
_before: dict[int, Any] = {}  # signal number -> the handler ours replaced
_options = SignalHandlerOptions.NO
_SIGNALS = ((SignalHandlerOptions.SIGINT, signal.SIGINT),
            (SignalHandlerOptions.SIGTERM, signal.SIGTERM))


def watch(context: Any) -> None:
    """Interrupt `context` when a handled signal comes (rclpy.init calls it)."""
    _contexts.add(context)


def install_signal_handlers(options: SignalHandlerOptions = SignalHandlerOptions.ALL) -> None:
    """Handle SIGINT, SIGTERM, both or neither (`options`); a no-op off the main thread,
    where Python cannot install signal handlers."""
    global _options
    if threading.current_thread() is not threading.main_thread():
        return
    for flag, number in _SIGNALS:
        if options & flag and number not in _before:
            _before[number] = signal.getsignal(number)
            signal.signal(number, _handle)
    _options = SignalHandlerOptions(_options | options)


def get_current_signal_handlers_options() -> SignalHandlerOptions:
    """Which signals rclpy's handlers handle now."""
    return _options


def uninstall_signal_handlers() -> None:
    """Put back the handlers that were there before rclpy's."""
    global _options
    if threading.current_thread() is threading.main_thread():
        for number, before in list(_before.items()):
            signal.signal(number, before if before is not None else signal.SIG_DFL)
            del _before[number]
    _options = SignalHandlerOptions.NO


def _handle(number: int, frame: Any) -> None:
    for context in list(_contexts):
        context.interrupt()
    for guard in list(_guards):
        guard.trigger()
    before = _before.get(number)
    if callable(before):
        before(number, frame)
    elif number == signal.SIGTERM and before in (signal.SIG_DFL, None):
        raise ExternalShutdownException()


class SignalHandlerGuardCondition(GuardCondition):
    """A guard condition that a handled signal triggers (executors wait on one to wake)."""

    def __init__(self, context: Any = None) -> None:
        super().__init__(callback=None, callback_group=None, context=context)
        _guards.add(self)

    def destroy(self) -> None:
        """Stop being triggered by signals."""
        _guards.discard(self)
        super().destroy()
