"""The job host (`python -m launcher.batch.host`): runs one job on a node, as a Ray task asks.

It reads the job's spec as one JSON line on stdin, and keeps stdin as its lifeline: a line
`stop <why>` or the end of stdin (the task's worker died) stops the job. It owns the job: its
folder, its private graph, its time limit, the stop of its whole tree, and a watchdog (forked
first, on the job's mark) that ends everything the job started even if the host is killed.
At the end it prints one JSON line: the job's result and where its packed folder is.
Standard library and launcher's process helpers only: every job pays for these imports."""

from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from launcher import lineage
from launcher.batch import archive
from launcher.batch.job import (
    JOB_MARK_PREFIX,
    SCRATCH_VARIABLE,
    JobFolder,
    JobSpec,
    command,
    environment,
)
from launcher.batch.outcome import Ending, judge
from launcher.batch.stopping import Escalation, sweep
from launcher.dispositions import reset_for_children
from launcher.runtime import reaper
from launcher.runtime.loop import EventLoop

POLL = 0.05  # seconds between looks at the job where the system has no pidfd
STOP_SIGNALS = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)


class JobHost:
    def __init__(self, spec: JobSpec, mark: str, lifeline: Lifeline, loop: EventLoop,
                 watchdog_fd: int | None = None) -> None:
        self.spec = spec
        self.lifeline = lifeline
        self.loop = loop
        self.mark = mark
        self.watchdog_fd = watchdog_fd
        self.folder = JobFolder(Path(tempfile.mkdtemp(prefix=f"lnb-{spec.id}-")))
        self.run_dir = tempfile.mkdtemp(prefix="lng-")  # the job's graph: a short socket path
        self.stopped_for: str | None = None
        self.escalation: Escalation | None = None
        self.lost = False  # the lifeline closed

    def run(self) -> Ending:
        """Start the job and follow it to its end."""
        self.folder.make()
        root = Path(self.spec.root) if self.spec.root else Path.cwd()
        argv = command(self.spec, self.folder, sys.executable, root)
        env = environment(self.spec, dict(os.environ), self.folder, self.run_dir, root,
                          self.mark)
        started, clock = time.time(), time.monotonic()
        with open(self.folder.console, "wb") as console:
            child = subprocess.Popen(argv, cwd=root, env=env, stdin=subprocess.DEVNULL,
                                     stdout=console, stderr=subprocess.STDOUT,
                                     start_new_session=True)
        self._tell(f"+{child.pid}")
        self.escalation = Escalation(child.pid, self.loop)
        code = self._follow(child)
        wall = time.monotonic() - clock
        left = sweep(self.mark)
        self._tell(f"-{child.pid}")
        shutil.rmtree(self.run_dir, ignore_errors=True)
        return Ending(code, self.stopped_for, wall, started, left)

    def _follow(self, child: subprocess.Popen[bytes]) -> int:
        """The loop until the job exits: its lifeline, its time limit, signals."""
        exited = _pidfd(child.pid)
        if exited is not None:
            self.loop.add_reader(exited, self.loop.stop)
        else:
            self._poll(child)
        self.loop.add_reader(self.lifeline.fd, self._on_lifeline)
        limit = self.loop.call_later(self.spec.timeout, self.stop, "timeout")
        for signum in STOP_SIGNALS:
            self.loop.add_signal_handler(signum,
                                         lambda n: self.stop(signal.Signals(n).name))
        try:
            self.loop.run()
            return child.wait()
        finally:
            limit.cancel()
            if exited is not None:
                self.loop.remove_reader(exited)
                os.close(exited)

    def _poll(self, child: subprocess.Popen[bytes]) -> None:
        if child.poll() is None:
            self.loop.call_later(POLL, self._poll, child)
        else:
            self.loop.stop()

    def _on_lifeline(self) -> None:
        for line in self.lifeline.read():
            if line.startswith(b"stop"):
                self.stop(line[4:].strip().decode() or "cancelled")
        if self.lifeline.closed:  # the worker that started the host is gone (or was ended
            self.loop.remove_reader(self.lifeline.fd)  # by a second Ctrl-C): no more waiting
            self.lost = True
            if self.stopped_for is not None:
                self.escalation.hurry()  # type: ignore[union-attr]
            self.stop("lost")

    def stop(self, why: str) -> None:
        """Stop the job, for `why` (the first reason is the one told)."""
        if self.stopped_for is None:
            self.stopped_for = why
            self.escalation.start()  # type: ignore[union-attr]

    def _tell(self, line: str) -> None:
        if self.watchdog_fd is not None:
            os.write(self.watchdog_fd, f"{line}\n".encode())


def _pidfd(pid: int) -> int | None:
    try:
        return os.pidfd_open(pid)
    except (AttributeError, OSError):  # no pidfd here: the loop polls for the exit
        return None


class Lifeline:
    """stdin, read raw: the spec's line, then `stop` lines; its end means the worker died."""

    def __init__(self, fd: int = 0) -> None:
        self.fd = fd
        self.pending = b""
        self.closed = False

    def first_line(self) -> bytes:
        while b"\n" not in self.pending and not self.closed:
            self._read()
        line, _, self.pending = self.pending.partition(b"\n")
        return line

    def read(self) -> list[bytes]:
        """What came (the fd is readable): its whole lines."""
        self._read()
        *lines, self.pending = self.pending.split(b"\n")
        return [line for line in lines if line.strip()]

    def _read(self) -> None:
        chunk = os.read(self.fd, 4096)
        self.closed = not chunk
        self.pending += chunk


def main() -> int:
    # A Ray worker starts its children with SIGINT blocked; a job starts as it does from a
    # shell, where Ctrl-C reaches every process of it.
    signal.pthread_sigmask(signal.SIG_SETMASK, set())
    lifeline = Lifeline()
    spec = JobSpec.from_json(lifeline.first_line().decode())
    mark = JOB_MARK_PREFIX + os.urandom(8).hex()
    lineage.become_subreaper()
    _pid, watchdog_fd = reaper.fork_watchdog(mark)  # first: before any thread or child
    host = JobHost(spec, mark, lifeline, EventLoop(), watchdog_fd)
    reset_for_children()  # SIGQUIT too, if the worker ignored it
    ending = host.run()
    if host.lost:  # no one to answer: leave nothing behind
        _clear(host)
        return 0
    result = judge(spec, host.folder, ending)
    nothing_left = not lineage.marked(mark)  # (else the watchdog looks, and ends it)
    (host.folder.root / "result.json").write_text(json.dumps(result.to_json()))
    packed = archive.pack(host.folder.root)
    shutil.rmtree(host.folder.root, ignore_errors=True)
    try:
        sys.stdout.write(json.dumps({"result": result.to_json(), "archive": str(packed)}) +
                         "\n")
        sys.stdout.flush()
    except BrokenPipeError:  # the task is gone after all
        packed.unlink(missing_ok=True)
        _clear(host)
    if nothing_left:
        os.write(watchdog_fd, b"=\n")
    return 0


def _clear(host: JobHost) -> None:
    """Remove what the job left in this node's temporary folders."""
    shutil.rmtree(host.folder.root, ignore_errors=True)
    if os.environ.get(SCRATCH_VARIABLE):  # the task's folder for the job, which is gone
        shutil.rmtree(os.environ[SCRATCH_VARIABLE], ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
