"""The warm start: a launch's Python processes forked from a server that has already imported
what they import (runtime/warm_server.py), instead of each a new interpreter importing it all
again.

A process is started warm only when the server runs it exactly as its own interpreter would:
- its program is a Python script for this launcher's interpreter: argv[0] a file whose `#!`
  line names `python3` or `python` (directly or through `env`) that resolves, on the
  process's PATH, to this interpreter; or argv[0] this interpreter itself, followed by a
  script or `-m MODULE` and no interpreter options;
- its working directory exists, and it has no terminal;
- the variables that shape an interpreter's start (KEY_VARIABLES) are those of a server: one
  server per such environment, ended with the launch.
A server is started when the second process for it comes (that one still starts cold: its
server is importing meanwhile), and the third on start from it: a launch of one Python node
spends nothing on a server, which costs more than the one start it would save (its imports
are the node's own, and more). A server for launcher's own nodes (`-m
launcher.packages.entry launcher.….MODULE:FUNCTION`) imports that module too.
Otherwise, or when its server cannot be used, the process starts cold, as it always did.
`LAUNCHER_WARM_START=0` turns the warm start off.
"""

from __future__ import annotations

import contextlib
import json
import os
import signal
import subprocess
import sys
from typing import TYPE_CHECKING

from launcher.records import dataclass

if TYPE_CHECKING:  # (socket is imported by the first server: ~1 ms of every launch's start)
    import socket

VARIABLE = "LAUNCHER_WARM_START"
READY_WAIT = 5.0  # seconds a server may take to import before it is given up (cold from then)
ANSWER_WAIT = 30.0  # and to fork a process it was asked for
KEY_VARIABLES = ("PYTHONPATH", "PYTHONHOME", "PYTHONSAFEPATH", "PYTHONNOUSERSITE",
                 "PYTHONDONTWRITEBYTECODE", "PYTHONOPTIMIZE", "PYTHONHASHSEED", "PYTHONUTF8",
                 "PYTHONIOENCODING", "PYTHONWARNINGS", "PYTHONDEVMODE", "PYTHONTRACEMALLOC",
                 "PYTHONPYCACHEPREFIX", "PYTHONSTARTUP", "LANG", "LC_ALL", "LC_CTYPE",
                 "LAUNCHER_ROS_MODULES", "MUJOCO_GL", "PYOPENGL_PLATFORM", "LD_LIBRARY_PATH",
                 "LD_PRELOAD", "HOME", "PYTHONUSERBASE", "PYTHONFAULTHANDLER", "PYTHONMALLOC",
                 "PYTHONVERBOSE", "TZ", "AMENT_PREFIX_PATH", "LAUNCHER_PACKAGE_PATH")
# What nodes import: the node APIs and the message packages most of them use
PRELOAD = ("rclpy", "rclpy.node", "rclpy.executors", "rclpy.qos", "std_msgs.msg",
           "geometry_msgs.msg", "sensor_msgs.msg", "nav_msgs.msg", "tf2_ros")
PYTHON_NAMES = ("python3", "python")
ENTRY = "launcher.packages.entry"  # (how a package's entry points run: packages/executables.py)


@dataclass(frozen=True)
class Plan:
    run: str  # "script" or "module"
    target: str  # the script's path, or the module's name
    argv: list[str]  # the program's own arguments
    shown: list[str]  # the command line the process would have had cold (/proc/PID/cmdline)
    comm: str  # and its name (/proc/PID/comm)


def planned(argv: list[str], env: dict[str, str], cwd: str | None,
            python: str = sys.executable) -> Plan | None:
    """How the server would run `argv`, or None when it must start cold."""
    import shutil  # (here: ~2 ms of every launch's start otherwise)

    if not argv or env.get(VARIABLE) == "0" or env.get("PYTHONSAFEPATH") or \
            (cwd is not None and not os.path.isdir(cwd)):
        return None
    folder = cwd or os.getcwd()
    if os.sep in argv[0]:  # (a relative one: from the process's folder, as exec finds it)
        program: str | None = os.path.abspath(os.path.join(folder, argv[0]))
        named = argv[0]
    else:  # (found on PATH: exec is given the whole path, and passes it on to a script's
        program = named = shutil.which(argv[0], path=env.get("PATH"))  # interpreter)
    if program is None or named is None:
        return None
    if _same_interpreter(program, python):
        return _interpreter_args(argv, folder, os.path.basename(program))
    shebang = _shebang(program)
    if shebang is None:
        return None
    interpreter, through_env = shebang
    found = shutil.which(interpreter, path=env.get("PATH")) if through_env else interpreter
    if found is None or not _same_interpreter(found, python):
        return None
    # (as the kernel runs a script: the interpreter as the #! line, or env, names it, then
    # the script as exec was given it; its name is the script's, or the interpreter's when
    # env ran that)
    return Plan("script", program, argv[1:], [interpreter, named, *argv[1:]],
                os.path.basename(found if through_env else program))  # type: ignore[call-arg]


def _same_interpreter(path: str, python: str) -> bool:
    """Whether `path` starts as `python` would: the same file, from the same folder (a venv's
    python and the system's are one file, but not one interpreter: each finds its own
    packages from the folder it was started from)."""
    return os.path.realpath(path) == os.path.realpath(python) and \
        os.path.dirname(os.path.abspath(path)) == os.path.dirname(os.path.abspath(python))


def _interpreter_args(argv: list[str], folder: str, comm: str) -> Plan | None:
    """`python SCRIPT ARGS…` or `python -m MODULE ARGS…`: anything else (options, -c, no
    script, a zip application or a .pyc file) starts cold."""
    words = argv[1:]
    if len(words) >= 2 and words[0] == "-m":
        return Plan("module", words[1], words[2:], argv, comm)  # type: ignore[call-arg]
    if not words or words[0].startswith("-"):
        return None
    script = os.path.abspath(os.path.join(folder, words[0]))
    if not _source(script):
        return None
    return Plan("script", script, words[1:], argv, comm)  # type: ignore[call-arg]


def _source(path: str) -> bool:
    """Whether `path` is a Python source file (not a zip application, nor compiled)."""
    from importlib.util import MAGIC_NUMBER

    try:
        with open(path, "rb") as handle:
            start = handle.read(4)
    except OSError:
        return False
    return start not in (b"PK\x03\x04", MAGIC_NUMBER)


def _shebang(path: str) -> tuple[str, bool] | None:
    """The Python its `#!` line names, and whether through `env` (`#!/usr/bin/python3`,
    `#!/usr/bin/env python3`), or None when it is not a Python script, or not one the kernel
    would run as written (a relative interpreter, a carriage return, options)."""
    try:
        with open(path, "rb") as script:
            first = script.readline(256)
    except OSError:
        return None
    line = first.removesuffix(b"\n")
    if not line.startswith(b"#!") or b"\r" in line or not _source(path):
        return None
    words = line[2:].decode(errors="replace").split()
    if not words or not os.path.isabs(words[0]):
        return None
    through_env = os.path.basename(words[0]) == "env"
    if through_env:
        words = words[1:]
    if len(words) != 1 or os.path.basename(words[0]) not in PYTHON_NAMES:
        return None  # (interpreter options, `env -S`: cold)
    return words[0], through_env


def own_module(plan: Plan) -> tuple[str, ...]:
    """The module of launcher's own node that `plan` runs (a server for it imports it too)."""
    if plan.run != "module" or plan.target != ENTRY or not plan.argv:
        return ()
    module = plan.argv[0].partition(":")[0]
    return (module,) if module.startswith("launcher.") else ()


def key(env: dict[str, str]) -> tuple[str, ...]:
    return tuple(env.get(name, "\0") for name in KEY_VARIABLES)


class Server:
    """One warm server: its process and the socket its requests go on."""

    def __init__(self, env: dict[str, str], python: str, modules: tuple[str, ...]) -> None:
        import socket

        ours, theirs = socket.socketpair(socket.AF_UNIX, socket.SOCK_STREAM)
        try:
            self.process = subprocess.Popen(
                [python, "-m", "launcher.runtime.warm_server", f"--fd={theirs.fileno()}"],
                env=env, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                stderr=subprocess.DEVNULL, pass_fds=(theirs.fileno(),), start_new_session=True)
        except BaseException:
            ours.close()
            raise
        finally:
            theirs.close()
        self.channel: socket.socket = ours
        self.ready: bool | None = None  # (it says so once it has imported what it imports)
        try:
            self._send({"modules": list(modules)}, [])  # (its first request: what to import)
        except OSError:
            self.close()
            raise

    def start(self, plan: Plan, env: dict[str, str], cwd: str, fds: list[int]) -> int:
        """The pid of the process it forked (OSError or ValueError when it could not)."""
        if self.ready is None:
            self.channel.settimeout(READY_WAIT)
            self.ready = bool(json.loads(self._line()).get("ready"))
        if not self.ready:
            raise OSError("a process started warm here could not look as it would cold")
        self.channel.settimeout(ANSWER_WAIT)
        self._send({"run": plan.run, "target": plan.target, "argv": plan.argv,
                    "shown": plan.shown, "comm": plan.comm, "env": env, "cwd": cwd}, fds)
        try:
            pid = json.loads(self._line())["pid"]
        except (OSError, ValueError):
            # (asked, and no answer: its fork may be under way. The server and what it forks
            # before the process has a session of its own end here, not with the launch)
            with contextlib.suppress(OSError):
                os.killpg(self.process.pid, signal.SIGKILL)
            raise
        if pid <= 0:
            raise OSError("the warm start's server could not fork")
        return pid

    def _send(self, request: dict, fds: list[int]) -> None:
        """A request as the server reads one: its length (with `fds`), then its JSON."""
        import socket

        body = json.dumps(request).encode()
        socket.send_fds(self.channel, [len(body).to_bytes(8, "little")], fds)
        self.channel.sendall(body)

    def _line(self) -> bytes:
        answer = b""
        while not answer.endswith(b"\n"):
            chunk = self.channel.recv(256)
            if not chunk:
                raise ConnectionError("the warm start's server ended")
            answer += chunk
        return answer

    def close(self) -> None:
        self.channel.close()  # (its end: the server exits)
        try:
            self.process.wait(1.0)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()


class WarmStarts:
    """The launch's servers, by environment; a server that failed is not asked again."""

    def __init__(self, python: str = sys.executable,
                 modules: tuple[str, ...] = PRELOAD) -> None:
        self.python, self.modules = python, modules
        self._servers: dict[tuple[str, ...], Server | None] = {}
        self._seen: set[tuple[str, ...]] = set()  # (kinds one process has started cold for)
        self._closed = False  # (the launch is ending: a process started now starts cold)

    def start(self, argv: list[str], env: dict[str, str], cwd: str | None,
              fds: list[int]) -> int | None:
        """The pid of `argv` started warm, or None: start it cold."""
        plan = None if self._closed else planned(argv, env, cwd, self.python)
        if plan is None:
            return None
        own = own_module(plan)
        which = (*key(env), own)
        if which not in self._seen:
            self._seen.add(which)  # (the first of its kind: cold, and no server yet)
            return None
        if which not in self._servers:
            try:
                self._servers[which] = Server(env, self.python, (*self.modules, *own))
            except OSError:
                self._servers[which] = None
            return None  # (the second: cold too, while its server imports)
        server = self._servers[which]
        if server is None:
            return None
        try:
            return server.start(plan, env, cwd or os.getcwd(), fds)
        except (OSError, ValueError):
            self._servers[which] = None  # (given up: cold from now on)
            with contextlib.suppress(OSError):
                server.close()
            return None

    def close(self) -> None:
        self._closed = True
        for server in self._servers.values():
            if server is not None:
                server.close()
        self._servers.clear()


def warm_starts(env: dict[str, str]) -> WarmStarts | None:
    """The launch's warm starts, unless its environment turns them off."""
    return None if env.get(VARIABLE) == "0" else WarmStarts()
