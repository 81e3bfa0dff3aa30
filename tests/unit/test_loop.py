import contextlib
import os
import signal
import subprocess
import sys

from launcher.runtime.loop import EventLoop
from tests.support.environment import REPO


class FakeClock:
    def __init__(self):
        self.now = 100.0

    def __call__(self):
        return self.now


def test_timers_run_in_order_and_cancel():
    clock = FakeClock()
    loop = EventLoop(clock)
    seen = []
    loop.call_later(2.0, seen.append, "late")
    loop.call_later(1.0, seen.append, "early")
    cancelled = loop.call_later(1.5, seen.append, "cancelled")
    cancelled.cancel()
    loop.call_soon(seen.append, "soon")
    loop._run_once()
    assert seen == ["soon"]
    clock.now += 2.0
    loop.call_later(0.1, loop.stop)
    loop._run_once()
    assert seen == ["soon", "early", "late"]
    loop.close()


def test_readers_and_signals_reach_the_loop():
    loop = EventLoop()
    read, write = os.pipe()
    got = []

    def on_read():
        got.append(os.read(read, 10))
        loop.remove_reader(read)
        os.kill(os.getpid(), signal.SIGUSR1)

    loop.add_reader(read, on_read)
    loop.add_signal_handler(signal.SIGUSR1, lambda sig: (got.append(sig), loop.stop()))
    os.write(write, b"ping")
    loop.run()
    loop.close()
    os.close(read)
    os.close(write)
    assert got == [b"ping", signal.SIGUSR1]
    assert signal.getsignal(signal.SIGUSR1) == signal.SIG_DFL


def test_the_launch_service_and_the_tests_fake_are_both_runtimes():
    from launcher.runtime.context import Runtime
    from launcher.runtime.service import LaunchService
    from tests.support.fake_service import FakeService

    assert isinstance(FakeService(), Runtime)
    assert isinstance(LaunchService(), Runtime)


def test_work_posted_from_other_threads_runs_on_the_loop_in_order():
    import threading

    loop = EventLoop()
    loop.open_posting()
    seen: list[tuple[int, bool]] = []

    def post(number: int) -> None:
        loop.call_soon_threadsafe(lambda: seen.append(
            (number, threading.current_thread() is threading.main_thread())))

    workers = [threading.Thread(target=post, args=(i,)) for i in range(3)]
    for worker in workers:
        worker.start()
        worker.join()
    loop.call_later(0.2, loop.stop)
    loop.run()
    loop.close()
    assert seen == [(0, True), (1, True), (2, True)]


def test_work_posted_to_a_closed_loop_is_refused_not_written_to_its_closed_pipe():
    loop = EventLoop()
    loop.open_posting()
    loop.close()
    assert loop.call_soon_threadsafe(lambda: None) is False


def test_a_signal_inside_a_shielded_section_waits_for_the_loop():
    from launcher.errors import Interrupted

    loop = EventLoop()
    got = []
    loop.add_signal_handler(signal.SIGINT, lambda sig: (got.append(sig), loop.stop()))
    try:
        with loop.interruptible():
            with loop.shielded():
                os.kill(os.getpid(), signal.SIGINT)  # handled in here: must not raise
                got.append("recorded")
            with_raise = False
            try:
                os.kill(os.getpid(), signal.SIGINT)  # interruptible again: raises
            except Interrupted as exc:
                loop.took(exc.signum)
                with_raise = True
        loop.run()  # the shielded one's byte reaches the handler; the raised one's does not
    finally:
        loop.close()
    assert with_raise
    assert got == ["recorded", signal.SIGINT]


def test_a_signal_raised_where_something_swallows_it_still_reaches_the_loop():
    """Raised as Interrupted inside code that catches everything (a library's `except
    BaseException: pass`, a __del__): the loop hands it to its handler at its next turn."""
    loop = EventLoop()
    got = []
    loop.add_signal_handler(signal.SIGTERM, lambda sig: (got.append(sig), loop.stop()))
    try:
        with loop.interruptible(), contextlib.suppress(BaseException):  # (what a careless
            os.kill(os.getpid(), signal.SIGTERM)  # library does)
        loop.call_later(5.0, loop.stop)  # (the test's own bound)
        loop.run()
    finally:
        loop.close()
    assert got == [signal.SIGTERM]


def test_a_signal_the_replaced_handler_raised_and_nothing_acted_on_is_received_again():
    """The command's first handler (cli/entry.py's) raised it while the launch was read, and
    code that catches everything went on: the loop takes it over with the signals."""
    def first(_signum, _frame):
        raise KeyboardInterrupt

    first.take_raised = lambda: [(signal.SIGINT, "careless.launch.py:9")]
    previous = signal.signal(signal.SIGINT, first)
    loop = EventLoop()
    got = []
    try:
        unacted = loop.add_signal_handler(signal.SIGINT, lambda sig: (got.append(sig),
                                                                      loop.stop()))
        loop.call_later(5.0, loop.stop)  # (the test's own bound)
        loop.run()
    finally:
        loop.close()
        signal.signal(signal.SIGINT, previous)
    assert unacted == [(signal.SIGINT, "careless.launch.py:9")]
    assert got == [signal.SIGINT]


def test_a_sigterm_is_not_lost_when_a_storm_of_sigchld_has_filled_the_wakeup_pipe():
    """A respawn storm sends SIGCHLD faster than a slow handler takes them: the wakeup pipe
    fills and the interpreter drops bytes. A SIGTERM then must still reach its handler, and
    the SIGCHLDs that came together are handled once."""
    loop = EventLoop()
    got = []
    loop.add_signal_handler(signal.SIGTERM, got.append)
    loop.add_signal_handler(signal.SIGCHLD, got.append)
    try:
        filled = 0
        while True:  # the pipe full, as the storm leaves it
            try:
                filled += os.write(loop._wakeup[1], bytes([signal.SIGCHLD]) * 4096)
            except BlockingIOError:
                break
        assert filled >= 4096
        for _ in range(3):
            os.kill(os.getpid(), signal.SIGCHLD)
        os.kill(os.getpid(), signal.SIGTERM)  # its byte cannot go in: the pipe is full
        for _ in range(200):  # (the bytes are read 4096 at a time)
            loop._run_once() if got.count(signal.SIGTERM) == 0 else None
        assert got.count(signal.SIGTERM) == 1
        assert 1 <= got.count(signal.SIGCHLD) <= 3
    finally:
        loop.close()


TRACED = """
import os, signal
from launcher.runtime.loop import EventLoop
loop = EventLoop()
loop.add_signal_handler(signal.SIGTERM, lambda sig: loop.stop())
loop.call_later(0.0, os.kill, os.getpid(), signal.SIGTERM)
loop.call_later(5.0, loop.stop)
loop.run()
"""


def test_each_signal_seen_and_handled_is_traced_where_asked(tmp_path):
    """LAUNCHER_SIGNAL_TRACE: the file bench/signals.py prints for a lost signal."""
    traced = tmp_path / "trace.txt"
    done = subprocess.run([sys.executable, "-c", TRACED], cwd=REPO, timeout=30,
                          env={**os.environ, "LAUNCHER_SIGNAL_TRACE": str(traced)})
    assert done.returncode == 0
    lines = [line.split(" ", 2)[2] for line in traced.read_text().splitlines()]
    assert lines == ["loop 15 busy=0", "handled {15: 1}"]
