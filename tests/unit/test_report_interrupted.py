"""A signal that lands inside a library's `try` whose cleanup then fails (argparse's
parse_intermixed_args restores attributes it never saved) is reported as the signal: the
status a shell expects, and nothing printed (found by the fault campaign)."""

from __future__ import annotations

import subprocess
import sys

import pytest

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


# A signal that lands in a weakref callback (importing runs them; so does a collection while
# a launch file loads) raises there, where Python can only print the exception and go on.
SWALLOWED = """
import signal, time, weakref
from launcher.cli import entry
from launcher.runtime.loop import EventLoop
entry._running = True
loop = EventLoop()
RAISERS = {{
    "entry": lambda _: entry._interrupt(signal.SIGINT, None),  # the command's first handler
    "loop": lambda _: loop._on_signal(signal.SIGINT, None),  # the launch's, while it is busy
}}
loop.add_signal_handler(signal.SIGINT, lambda signum: print("HANDED TO THE LOOP", signum))

class Thing:
    pass

try:
    with loop.interruptible():
        thing = Thing()
        ref = weakref.ref(thing, RAISERS["{raiser}"])
        del thing
        for _ in range(200):
            time.sleep(0.01)
    print("NOT INTERRUPTED")
except KeyboardInterrupt as exc:
    print("INTERRUPTED", exc.signum)
"""


@pytest.mark.parametrize("raiser", ["entry", "loop"])
def test_a_signal_raised_where_python_cannot_raise_is_sent_again_not_lost(raiser):
    """The signal is sent again instead, and ends the command as any other: by the command's
    own handler, and by the launch's event loop's (a signal printed and lost there left the
    launch running: the lost early signal under load)."""
    done = subprocess.run([sys.executable, "-c", SWALLOWED.format(raiser=raiser)],
                          capture_output=True, text=True, timeout=30, cwd=REPO)
    assert done.stdout.strip() == "INTERRUPTED 2", done.stdout + done.stderr
    assert "Traceback" not in done.stderr and "Exception ignored" not in done.stderr


SECOND_SIGNAL = """
import signal
from launcher.cli import entry
entry._running = True
try:
    entry._interrupt(signal.SIGTERM, None)  # the first: raised, to end the command
except KeyboardInterrupt:
    print("the first raised", flush=True)
    entry._interrupt(signal.SIGINT, None)  # the next, inside its handling: ends it now
print("not reached", flush=True)
"""


def test_a_second_signal_while_the_first_is_handled_ends_the_command_with_its_status():
    """Raised again, it could land in main()'s own handling of the first and escape it (the
    interpreter would then die by the signal, not exit with its status)."""
    done = subprocess.run([sys.executable, "-c", SECOND_SIGNAL], capture_output=True, text=True,
                          timeout=60, cwd=REPO)
    assert done.returncode == 130, done.stderr
    assert done.stdout == "the first raised\n"
