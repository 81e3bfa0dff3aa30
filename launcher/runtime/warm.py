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
import subprocess
import sys
from typing import TYPE_CHECKING

from launcher.records import dataclass

if TYPE_CHECKING:  # (socket is imported by the first server: ~1 ms of every launch's start)
    import socket

VARIABLE = "LAUNCHER_WARM_START"
ANSWER_WAIT = 5.0  # seconds a server may take to answer before it is given up (cold from then)
KEY_VARIABLES = ("PYTHONPATH", "PYTHONHOME", "PYTHONSAFEPATH", "PYTHONNOUSERSITE",
                 "PYTHONDONTWRITEBYTECODE", "PYTHONOPTIMIZE", "PYTHONHASHSEED", "PYTHONUTF8",
                 "PYTHONIOENCODING", "PYTHONWARNINGS", "PYTHONDEVMODE", "PYTHONTRACEMALLOC",
                 "PYTHONPYCACHEPREFIX", "PYTHONSTARTUP", "LANG", "LC_ALL", "LC_CTYPE",
                 "LAUNCHER_ROS_MODULES", "MUJOCO_GL", "PYOPENGL_PLATFORM")
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
    comm: str  # and its name (/proc/PID/comm: the interpreter's file's name)


def planned(argv: list[str], env: dict[str, str], cwd: str | None,
            python: str = sys.executable) -> Plan | None:
    """How the server would run `argv`, or None when it must start cold."""
    import shutil  # (here: ~2 ms of every launch's start otherwise)

    if not argv or env.get(VARIABLE) == "0" or (cwd is not None and not os.path.isdir(cwd)):
        return None
    here = os.path.realpath(python)
    program = shutil.which(argv[0], path=env.get("PATH")) if os.sep not in argv[0] else argv[0]
    if program is None:
        return None
    if os.path.realpath(program) == here:
        return _interpreter_args(argv, cwd, os.path.basename(program))
    interpreter = _shebang(program)
    if interpreter is None:
        return None
    found = shutil.which(interpreter, path=env.get("PATH")) if os.sep not in interpreter \
        else interpreter
    if found is None or os.path.realpath(found) != here:
        return None
    # (as the kernel runs a script: its interpreter, as `env` or the #! line names it, then
    # the script as it was named)
    return Plan("script", program, argv[1:], [interpreter, argv[0], *argv[1:]],
                os.path.basename(found))  # type: ignore[call-arg]


def _interpreter_args(argv: list[str], cwd: str | None, comm: str) -> Plan | None:
    """`python SCRIPT ARGS…` or `python -m MODULE ARGS…`: anything else (options, -c, no
    script) starts cold."""
    words = argv[1:]
    if len(words) >= 2 and words[0] == "-m":
        return Plan("module", words[1], words[2:], argv, comm)
    if not words or words[0].startswith("-"):
        return None
    script = os.path.join(cwd or os.getcwd(), words[0])
    return Plan("script", script, words[1:], argv, comm) if os.path.isfile(script) else None


def _shebang(path: str) -> str | None:
    """The Python its `#!` line names (`python3`, `/usr/bin/python3`, or through `env`), or
    None when it is not a Python script (or not readable as one)."""
    try:
        with open(path, "rb") as script:
            first = script.readline(256)
    except OSError:
        return None
    if not first.startswith(b"#!"):
        return None
    words = first[2:].decode(errors="replace").split()
    if words[:1] and os.path.basename(words[0]) == "env":
        words = words[1:]
    if len(words) != 1 or os.path.basename(words[0]) not in PYTHON_NAMES:
        return None  # (interpreter options, `env -S`: cold)
    return words[0]


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
        finally:
            theirs.close()
        self.channel: socket.socket = ours
        self.channel.settimeout(ANSWER_WAIT)
        self._send({"modules": list(modules)}, [])  # (its first request: what to import)
        self.ready: bool | None = None  # (it says so once it has imported what it imports)

    def start(self, plan: Plan, env: dict[str, str], cwd: str, fds: list[int]) -> int:
        """The pid of the process it forked (OSError or ValueError when it could not)."""
        if self.ready is None:
            self.ready = bool(json.loads(self._line()).get("ready"))
        if not self.ready:
            raise OSError("a process started warm here could not look as it would cold")
        self._send({"run": plan.run, "target": plan.target, "argv": plan.argv,
                    "shown": plan.shown, "comm": plan.comm, "env": env, "cwd": cwd}, fds)
        pid = json.loads(self._line())["pid"]
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

    def start(self, argv: list[str], env: dict[str, str], cwd: str | None,
              fds: list[int]) -> int | None:
        """The pid of `argv` started warm, or None: start it cold."""
        plan = planned(argv, env, cwd, self.python)
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
        for server in self._servers.values():
            if server is not None:
                server.close()
        self._servers.clear()


def warm_starts(env: dict[str, str]) -> WarmStarts | None:
    """The launch's warm starts, unless its environment turns them off."""
    return None if env.get(VARIABLE) == "0" else WarmStarts()
