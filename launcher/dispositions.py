"""Every child starts with the default dispositions of the stop signals, whatever the launcher
inherited, as systemd starts a service.

A shell starts its background jobs (`launcher launch … &` in a script, CI's steps) with SIGINT
and SIGQUIT ignored, nohup starts its command with SIGHUP ignored, and an ignored signal stays
ignored across fork and exec: the launch's processes would then ignore the SIGINT that stops
them, and end only by SIGTERM or SIGKILL, without their own shutdown. A caught signal, though,
is reset to its default by exec. So an ignored one is caught by a handler that does nothing:
the launcher still ignores it, and what it starts gets the default. No `preexec_fn`, which
would cost every spawn its fast path (vfork).
"""

from __future__ import annotations

import signal
import threading

STOP_SIGNALS = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP, signal.SIGQUIT)


def _ignore(_signum: int, _frame: object) -> None:
    """SIG_IGN, as a handler (exec resets it)."""


def reset_for_children() -> None:
    """Before starting a child: the stop signals ignored here are caught instead (signals can
    only be set on the main thread; elsewhere the launcher's own set-up has done it)."""
    if threading.current_thread() is not threading.main_thread():
        return
    for sig in STOP_SIGNALS:
        if signal.getsignal(sig) is signal.SIG_IGN:
            signal.signal(sig, _ignore)
