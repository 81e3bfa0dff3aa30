"""Which processes belong to a launch, however far they wander (Linux /proc).

A process group is not enough: a child can leave it (`setsid`, `setpgid(0, 0)`, `set -m`) or
double-fork into a daemon. So a launch holds on to its processes two ways:

- It marks them. The launcher puts a variable of its own (`LAUNCHER_LAUNCH_<id>`) into the
  environment before it starts anything; children, grandchildren and daemons inherit it, and
  /proc/PID/environ shows it for as long as they live, whoever their parent is by then.
- It adopts them. The launcher is the child subreaper (`PR_SET_CHILD_SUBREAPER`): a
  descendant whose parent exits is reparented to the launcher, not to init, so while the
  launcher lives its process tree holds every descendant, marked or not.

A process that must outlive the launch (the graph's router) is started with `detached()`:
without the marks and with LAUNCHER_DETACHED set, which every sweep leaves alone.
"""

from __future__ import annotations

import contextlib
import os
import signal
import time
from collections.abc import Iterable, Mapping
from pathlib import Path

from launcher.dispositions import reset_for_children

MARK_PREFIX = "LAUNCHER_LAUNCH_"
DETACHED = "LAUNCHER_DETACHED"
# Set on a node a roslaunch file starts: its parameters as ROS 2's `--ros-args` words (JSON),
# for launcher's own nodes, since its command line is ROS 1's (rospy reads the server); the
# node takes them out of its environment, so that no process it starts inherits them.
NODE_PARAMETERS = "LAUNCHER_NODE_PARAMETERS"
_PR_SET_CHILD_SUBREAPER = 36
_PROC = Path("/proc")


def new_mark() -> str:
    """The environment variable that marks one launch's processes."""
    return MARK_PREFIX + os.urandom(8).hex()


def detached(env: Mapping[str, str]) -> dict[str, str]:
    """`env` for a process that is nobody's launch's: no marks, LAUNCHER_DETACHED set."""
    out = {k: v for k, v in env.items() if not k.startswith(MARK_PREFIX)}
    out[DETACHED] = "1"
    return out


def become_subreaper() -> bool:
    """Make this process the reaper of its orphaned descendants (Linux only)."""
    try:
        import ctypes  # only here: start-up time of the other commands

        libc = ctypes.CDLL(None, use_errno=True)
        return libc.prctl(_PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0) == 0
    except (OSError, AttributeError):
        return False


def children(pid: int) -> set[int]:
    """The direct children of `pid` (zombies included)."""
    found: set[int] = set()
    try:
        tasks = list((_PROC / str(pid) / "task").iterdir())
    except OSError:
        return found
    for task in tasks:
        with contextlib.suppress(OSError, ValueError):
            found.update(int(p) for p in (task / "children").read_text().split())
    return found


def environ(pid: int) -> bytes | None:
    """The environment `pid` was started with (None when gone or not ours to read)."""
    try:
        return (_PROC / str(pid) / "environ").read_bytes()
    except OSError:
        return None


def _has(env: bytes, name: str) -> bool:
    key = name.encode() + b"="
    return env.startswith(key) or b"\0" + key in env


def is_detached(pid: int) -> bool:
    env = environ(pid)
    return env is not None and _has(env, DETACHED)


def state(pid: int) -> str | None:
    """The one-letter state in /proc/PID/stat ('Z' for a zombie), None when gone."""
    try:
        text = (_PROC / str(pid) / "stat").read_bytes()
    except OSError:
        return None
    return text[text.rfind(b")") + 2:][:1].decode() or None


def alive(pid: int) -> bool:
    return state(pid) not in (None, "Z", "X")


def live_groups(pgids: set[int]) -> set[int]:
    """Those of `pgids` that still hold a process that is not a zombie (a group of zombies
    nobody collects is gone for our purposes)."""
    if not pgids:
        return set()
    found: set[int] = set()
    for entry in os.scandir(_PROC):
        if not entry.name.isdigit():
            continue
        try:
            text = (_PROC / entry.name / "stat").read_bytes()
        except OSError:
            continue
        fields = text[text.rfind(b")") + 2:].split()
        if len(fields) > 2 and fields[0] not in (b"Z", b"X") and int(fields[2]) in pgids:
            found.add(int(fields[2]))
            if found == pgids:
                break
    return found


def descendants(pid: int) -> set[int]:
    """Every live process below `pid`, except detached ones and what is below them."""
    found: set[int] = set()
    todo = [pid]
    while todo:
        for child in children(todo.pop()):
            if child not in found and alive(child) and not is_detached(child):
                found.add(child)
                todo.append(child)
    return found


def marked(mark: str) -> set[int]:
    """Every live process whose environment carries `mark` (that we may read)."""
    found = set()
    me = os.getpid()
    for entry in os.scandir(_PROC):
        if not entry.name.isdigit() or int(entry.name) == me:
            continue
        env = environ(int(entry.name))
        if env is not None and _has(env, mark) and alive(int(entry.name)):
            found.add(int(entry.name))
    return found


def signal_all(pids: Iterable[int], sig: int) -> None:
    for pid in pids:
        with contextlib.suppress(ProcessLookupError, PermissionError):
            os.kill(pid, sig)


def reap(pid: int) -> bool:
    """Collect `pid` if it is our child and has exited; True when it is gone."""
    try:
        done, _ = os.waitpid(pid, os.WNOHANG)
    except ChildProcessError:
        return not alive(pid)
    return done == pid


def run_to_end(argv: list[str], env: Mapping[str, str], *, cwd: str | None = None,
               merge_stderr: bool = False,
               timeout: float | None = None) -> tuple[int, bytes, bytes]:
    """Run a short-lived helper (a `$(command)`, a shell hook) in a session of its own:
    (exit status, stdout, stderr). Its output goes to unlinked files, not pipes, so a
    background job it leaves cannot hold the launch up; once it exits, whatever it left in its
    group is stopped. Interrupted (Ctrl-C) or past `timeout`, the whole group is stopped and
    the exception (subprocess.TimeoutExpired, with the output so far) goes on."""
    import subprocess  # only when a helper runs: a node's start-up time
    import tempfile

    reset_for_children()
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        child = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=out,
                                 stderr=subprocess.STDOUT if merge_stderr else err,
                                 env=dict(env), cwd=cwd, start_new_session=True)
        try:
            code = child.wait(timeout)
        except subprocess.TimeoutExpired as exc:  # what it said so far goes with it
            stop_group(child.pid)
            child.wait()
            out.seek(0)
            err.seek(0)
            exc.output, exc.stderr = out.read(), err.read()
            raise
        finally:
            stop_group(child.pid)
            if child.returncode is None:
                child.wait()
        out.seek(0)
        err.seek(0)
        return code, out.read(), err.read()


def stop_group(pgid: int, grace: float = 0.2) -> None:
    """SIGTERM the group, SIGKILL it after `grace` seconds if anything is left."""
    try:
        os.killpg(pgid, signal.SIGTERM)
    except (ProcessLookupError, PermissionError):
        return
    deadline = time.monotonic() + grace
    while time.monotonic() < deadline:
        try:
            os.killpg(pgid, 0)
        except ProcessLookupError:
            return
        time.sleep(0.01)
    with contextlib.suppress(ProcessLookupError, PermissionError):
        os.killpg(pgid, signal.SIGKILL)
