"""The launch's timers (TimerAction's, respawn delays): each firing is followed by a look at
whether the launch is done, and those marked so are cancelled when it shuts down."""

from __future__ import annotations

from collections.abc import Callable

from launcher.runtime.loop import EventLoop, Timer


class LaunchTimers:
    def __init__(self, loop: EventLoop, after_fire: Callable[[], None]) -> None:
        self.loop, self.after_fire = loop, after_fire
        self.live: dict[Timer, bool] = {}  # timer -> cancel on shutdown

    def add(self, period: float, callback: Callable[[], None],
            cancel_on_shutdown: bool = True) -> Timer:
        """`callback` after `period` seconds on the event loop."""
        def fire() -> None:
            self.live.pop(timer, None)
            callback()
            self.after_fire()

        timer = self.loop.call_later(period, fire)
        self.live[timer] = cancel_on_shutdown
        return timer

    def cancel(self) -> None:
        """The launch shuts down: the timers marked to stop, stop."""
        for timer, cancel in list(self.live.items()):
            if cancel:
                timer.cancel()
                del self.live[timer]
