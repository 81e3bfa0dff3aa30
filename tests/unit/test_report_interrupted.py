"""A signal that lands inside a library's `try` whose cleanup then fails (argparse's
parse_intermixed_args restores attributes it never saved) is reported as the signal: the
status a shell expects, and nothing printed (found by the fault campaign)."""

from __future__ import annotations

import subprocess
import sys

from launcher.errors import Interrupted, report
from tests.support.environment import REPO


def test_a_failure_while_handling_a_signal_is_the_signals(capsys):
    try:
        try:
            raise Interrupted(15)
        finally:
            raise AttributeError("'_StoreAction' object has no attribute 'save_nargs'")
    except AttributeError as exc:
        assert report(exc) == 143
    assert capsys.readouterr().err == ""


def test_other_failures_are_still_reported(capsys):
    try:
        try:
            raise ValueError("first")
        finally:
            raise AttributeError("second")
    except AttributeError as exc:
        assert report(exc) == 1
    assert "internal error: AttributeError: second" in capsys.readouterr().err


SWALLOWED = """
import time, weakref
from launcher.cli import entry
entry._running = True

class Thing:
    pass

try:
    thing = Thing()
    ref = weakref.ref(thing, lambda _: entry._interrupt(2, None))  # as importlib's callbacks
    del thing
    for _ in range(200):
        time.sleep(0.01)
    print("NOT INTERRUPTED")
except KeyboardInterrupt as exc:
    print("INTERRUPTED", exc.signum)
"""


def test_a_signal_raised_where_python_cannot_raise_is_sent_again_not_lost():
    """Ctrl-C landing in a weakref callback (importing runs them) raised there, where Python
    can only print the exception and go on: the signal is sent again instead, and ends the
    command as any other."""
    done = subprocess.run([sys.executable, "-c", SWALLOWED], capture_output=True, text=True,
                          timeout=30, cwd=REPO)
    assert done.stdout.strip() == "INTERRUPTED 2", done.stdout + done.stderr
    assert "Traceback" not in done.stderr and "Exception ignored" not in done.stderr


SWALLOWED_IN_THE_LOOP = """
import signal, time, weakref
from launcher.cli import entry
from launcher.errors import Interrupted
from launcher.runtime.loop import EventLoop
entry._running = True
loop = EventLoop()
loop.add_signal_handler(signal.SIGINT, lambda signum: print("HANDED TO THE LOOP", signum))

class Thing:
    pass

try:
    with loop.interruptible():  # the launcher loading a file, when a collection runs
        thing = Thing()
        ref = weakref.ref(thing, lambda _: loop._on_signal(signal.SIGINT, None))
        del thing
        for _ in range(200):
            time.sleep(0.01)
    print("NOT INTERRUPTED")
except Interrupted as exc:
    print("INTERRUPTED", exc.signum)
"""


def test_the_event_loops_interruption_raised_where_python_cannot_raise_is_not_lost():
    """The same for the launch's own event loop, whose handler raises its Interrupted while
    the launcher is busy: a signal landing in a finalizer then was printed and lost, and the
    launch went on running (the lost early signal under load)."""
    done = subprocess.run([sys.executable, "-c", SWALLOWED_IN_THE_LOOP], capture_output=True,
                          text=True, timeout=30, cwd=REPO)
    assert done.stdout.strip() == "INTERRUPTED 2", done.stdout + done.stderr
    assert "Exception ignored" not in done.stderr, done.stderr
