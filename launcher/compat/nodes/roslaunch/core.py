"""roslaunch.core: the values a ROS 1 launch is made of (Node, Test, Param, Machine, Master,
Executable), roslaunch's exception, and its printlog hooks. Plain data, as in roslaunch: what
runs them is launcher's runtime (roslaunch.launch)."""

from __future__ import annotations

import os
import socket
import sys
import uuid
from collections.abc import Callable
from typing import Any
from xml.sax.saxutils import quoteattr

PHASE_SETUP = "setup"
PHASE_RUN = "run"
PHASE_TEARDOWN = "teardown"
TEST_TIME_LIMIT_DEFAULT = 60
DEFAULT_MASTER_URI = "http://localhost:11311/"


class RLException(Exception):
    """roslaunch's error: a launch that cannot be loaded or run."""


# --- printlog: roslaunch's messages, also handed to the handlers configure_logging adds -----
_log_handlers: list[Callable[[str], Any]] = []
_error_handlers: list[Callable[[str], Any]] = []
_child_mode = False


def add_printlog_handler(h: Callable[[str], Any]) -> None:
    """Call `h(msg)` with every message printlog prints."""
    _log_handlers.append(h)


def add_printerrlog_handler(h: Callable[[str], Any]) -> None:
    """Call `h(msg)` with every message printerrlog prints."""
    _error_handlers.append(h)


def clear_printlog_handlers() -> None:
    """Forget the printlog handlers."""
    del _log_handlers[:]


def clear_printerrlog_handlers() -> None:
    """Forget the printerrlog handlers."""
    del _error_handlers[:]


def printlog(msg: str) -> None:
    """Print `msg` (not in child mode) and hand it to the printlog handlers."""
    for handler in _log_handlers:
        handler(msg)
    if not _child_mode:
        print(msg)


def printlog_bold(msg: str) -> None:
    """printlog, in bold on a terminal."""
    for handler in _log_handlers:
        handler(msg)
    if not _child_mode:
        print(f"\033[1m{msg}\033[0m" if sys.stdout.isatty() else msg)


def printerrlog(msg: str) -> None:
    """Print `msg` on stderr and hand it to the printerrlog handlers."""
    for handler in _error_handlers:
        handler(msg)
    print(f"\033[31m{msg}\033[0m" if sys.stderr.isatty() else msg, file=sys.stderr)


def set_child_mode(child_mode: bool) -> None:
    """roslaunch's child mode: printlog prints nothing (its handlers still get it)."""
    global _child_mode
    _child_mode = bool(child_mode)


def is_child_mode() -> bool:
    """Whether printlog is in child mode."""
    return _child_mode


def rle_wrapper(fn: Callable[..., Any]) -> Callable[..., Any]:
    """`fn`, raising RLException for any other exception it raises."""
    def wrapped_fn(*args: Any) -> Any:
        try:
            return fn(*args)
        except Exception as exc:
            raise RLException(f"ERROR: {exc}") from exc
    return wrapped_fn


# --- the run and its host ---------------------------------------------------------------------
def generate_run_id() -> str:
    """A new run id (a UUID, as roslaunch makes one)."""
    return str(uuid.uuid1())


def get_master_uri_env(*args: Any) -> str:
    """ROS_MASTER_URI, or roslaunch's default (launcher's graph needs no master: the URI
    only names one for code that prints it)."""
    return os.environ.get("ROS_MASTER_URI") or DEFAULT_MASTER_URI


def remap_localhost_uri(uri: str, force_localhost: bool = False) -> str:
    """`uri` with localhost (or, with `force_localhost`, this host's name) made the other."""
    host = socket.gethostname()
    if force_localhost:
        return uri.replace(host, "localhost")
    return uri.replace("localhost", host)


def setup_env(node: Node | None, machine: Machine | None, master_uri: str,
              env: dict[str, str] | None = None) -> dict[str, str]:
    """The environment of a node's process: `env` (os.environ), ROS_MASTER_URI, the node's
    namespace as ROS_NAMESPACE and its own variables."""
    made = dict(os.environ if env is None else env)
    made["ROS_MASTER_URI"] = master_uri
    if node is not None:
        made.pop("ROS_NAMESPACE", None)
        space = node.namespace.rstrip("/")
        if space:
            made["ROS_NAMESPACE"] = space
        made.update({str(k): str(v) for k, v in node.env_args})
    return made


class Master:
    """The ROS master a launch names. launcher's graph has none to start or ask: it is always
    there (its router starts with the first node), so `is_running` says True."""

    ROSMASTER = "rosmaster"
    ZENMASTER = "zenmaster"  # (roslaunch's old name)

    def __init__(self, type_: str | None = None, uri: str | None = None,
                 auto: Any = None) -> None:
        if auto is not None:
            raise RLException("'auto' is no longer a supported attribute")
        self.type = type_ or Master.ROSMASTER
        self.uri = uri or get_master_uri_env()
        self.auto = None

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Master) and (self.type, self.uri) == (other.type, other.uri)

    def __hash__(self) -> int:
        return hash((self.type, self.uri))

    def get_host(self) -> str:
        """The master URI's host."""
        from urllib.parse import urlparse

        return urlparse(self.uri).hostname or "localhost"

    def get_port(self) -> int:
        """The master URI's port."""
        from urllib.parse import urlparse

        return urlparse(self.uri).port or 11311

    def get(self) -> Any:
        """roslaunch's XML-RPC proxy of the master: launcher has none to give."""
        raise RLException("launcher's graph has no ROS 1 master to talk XML-RPC to")

    get_multi = get

    def is_running(self) -> bool:
        """Whether the master is up: launcher's graph always is."""
        return True


class Machine:
    """A host that nodes run on (`<machine>`)."""

    def __init__(self, name: str, address: str, env_loader: str | None = None,
                 ssh_port: int = 22, user: str | None = None, password: str | None = None,
                 assignable: bool = True, env_args: list[Any] = [],  # noqa: B006 (roslaunch's)
                 timeout: float | None = None) -> None:
        self.name, self.address, self.env_loader = name, address, env_loader
        self.ssh_port, self.user, self.password = ssh_port, user or None, password
        self.assignable, self.timeout = assignable, timeout or 10.0
        self.env_args = list(env_args)

    def __str__(self) -> str:
        return f"Machine(name[{self.name}] env_loader[{self.env_loader}] " \
               f"address[{self.address}] ssh_port[{self.ssh_port}] user[{self.user}] " \
               f"assignable[{self.assignable}] timeout[{self.timeout}])"

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Machine) and self.name == other.name and \
            self.config_equals(other)

    def __hash__(self) -> int:
        return hash((self.name, self.config_key()))

    def config_key(self) -> str:
        """What makes two machines the same host and login."""
        return f"Machine(address[{self.address}] env_loader[{self.env_loader}] " \
               f"ssh_port[{self.ssh_port}] user[{self.user}] password[{self.password}] " \
               f"assignable[{self.assignable}] timeout[{self.timeout}])"

    def config_equals(self, m2: Machine) -> bool:
        """Whether `m2` is the same host and login."""
        return isinstance(m2, Machine) and self.config_key() == m2.config_key()


def local_machine() -> Machine:
    """This host, as the machine nodes without one run on."""
    return Machine("", "localhost")


def is_machine_local(machine: Machine) -> bool:
    """Whether `machine` is this host."""
    if machine.address in ("localhost", "127.0.0.1", "::1", socket.gethostname()):
        return True
    try:
        address = socket.gethostbyname(machine.address)
    except OSError:
        return False
    return address.startswith("127.") or address in _local_addresses()


def _local_addresses() -> set[str]:
    try:
        return {info[4][0] for info in socket.getaddrinfo(socket.gethostname(), None)}
    except OSError:
        return set()


class Param:
    """A parameter the launch sets: `key` (a full name) and its value."""

    def __init__(self, key: str, value: Any) -> None:
        self.key = key if key.startswith("/") else f"/{key}"
        self.value = value

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Param) and (self.key, self.value) == (other.key, other.value)

    def __hash__(self) -> int:
        return hash(self.key)

    def __str__(self) -> str:
        return f"{self.key}={self.value}"

    __repr__ = __str__


class Executable:
    """A command the launch runs (`cmd args…`) in a phase: setup, run or teardown."""

    def __init__(self, cmd: str, args: Any, phase: str = PHASE_RUN) -> None:
        self.command, self.args, self.phase = cmd, args, phase

    def __str__(self) -> str:
        return f"{self.command} {' '.join(self.args)}"

    __repr__ = __str__


class RosbinExecutable(Executable):
    """An Executable from ROS's own bin folder."""

    def __str__(self) -> str:
        return f"ros/bin/{self.command} {' '.join(self.args)}"

    __repr__ = __str__


def _global_ns(namespace: str) -> str:
    space = namespace or "/"
    return (space if space.startswith("/") else f"/{space}").rstrip("/") + "/"


class Node:
    """A node to launch: `package`'s executable `node_type`, named `name` in `namespace`."""

    def __init__(self, package: str, node_type: str, name: str | None = None,
                 namespace: str = "/", machine_name: str | None = None, args: str = "",
                 respawn: bool = False, respawn_delay: float = 0.0,
                 remap_args: list[Any] | None = None, env_args: list[Any] | None = None,
                 output: str | None = None, cwd: str | None = None,
                 launch_prefix: str | None = None, required: bool = False,
                 filename: str = "<unknown>") -> None:
        self.package, self.type = package, node_type
        self.name = name or None
        self.namespace = _global_ns(namespace)
        self.machine_name = machine_name or None
        self.respawn, self.respawn_delay = respawn, respawn_delay
        self.args = args or ""
        self.remap_args = list(remap_args or [])
        self.env_args = list(env_args or [])
        self.output, self.cwd = output, cwd
        self.launch_prefix = launch_prefix or None
        self.required, self.filename = required, filename
        if self.name and "/" in self.name:
            raise ValueError(f"node name cannot contain a namespace: {self.name}")
        if self.respawn and self.required:
            raise ValueError("respawn and required cannot both be set to true")
        if self.cwd not in (None, "ros-root", "ROS_HOME", "node"):
            raise ValueError(f"cwd must be 'ROS_HOME' or 'node', not {self.cwd!r}")
        if self.output not in (None, "log", "screen"):
            raise ValueError(f"output must be 'log' or 'screen', not {self.output!r}")
        self.machine: Machine | None = None
        self.process_name: str | None = None

    def xmltype(self) -> str:
        """The tag of this node in a launch file."""
        return "node"

    def xmlattrs(self) -> list[tuple[str, Any]]:
        """The tag's attributes, as (name, value); a value None is left out."""
        return [("pkg", self.package), ("type", self.type), ("machine", self.machine_name),
                ("ns", self.namespace), ("args", self.args), ("output", self.output),
                ("cwd", self.cwd or None), ("respawn", self.respawn),
                ("respawn_delay", self.respawn_delay), ("name", self.name),
                ("launch-prefix", self.launch_prefix), ("required", self.required)]

    def to_xml(self) -> str:
        """This node as roslaunch XML (its private parameters are not kept)."""
        return self._xml(self.xmlattrs())

    def to_remote_xml(self) -> str:
        """to_xml without the machine attribute."""
        return self._xml([(a, v) for a, v in self.xmlattrs() if a != "machine"])

    def _xml(self, attrs: list[tuple[str, Any]]) -> str:
        def word(value: Any) -> str:
            return str(value).lower() if isinstance(value, bool) else str(value)
        words = " ".join(f"{a}={quoteattr(word(v))}" for a, v in attrs if v is not None)
        body = "".join(f"  <remap from={quoteattr(str(a))} to={quoteattr(str(b))} />\n"
                       for a, b in self.remap_args)
        body += "".join(f"  <env name={quoteattr(str(a))} value={quoteattr(str(b))} />\n"
                        for a, b in self.env_args)
        return f"<{self.xmltype()} {words}>\n{body}</{self.xmltype()}>"


class Test(Node):
    """A rostest `<test>`: a node run once, as the test named `test_name`."""

    def __init__(self, test_name: str, package: str, node_type: str, name: str | None = None,
                 namespace: str = "/", machine_name: str | None = None, args: str = "",
                 remap_args: list[Any] | None = None, env_args: list[Any] | None = None,
                 time_limit: float | None = None, cwd: str | None = None,
                 launch_prefix: str | None = None, retry: int | None = None,
                 filename: str = "<unknown>") -> None:
        super().__init__(package, node_type, name=name, namespace=namespace,
                         machine_name=machine_name, args=args, remap_args=remap_args,
                         env_args=env_args, output="log", cwd=cwd,
                         launch_prefix=launch_prefix, filename=filename)
        self.test_name = test_name
        self.retry = int(retry or 0)
        self.time_limit = float(TEST_TIME_LIMIT_DEFAULT if time_limit is None else time_limit)
        if self.time_limit <= 0:
            raise ValueError("'time-limit' must be a positive number")

    def xmltype(self) -> str:
        """The tag of this test in a launch file."""
        return "test"

    def xmlattrs(self) -> list[tuple[str, Any]]:
        """The tag's attributes (a test has no respawn nor output)."""
        attrs = [(a, v) for a, v in super().xmlattrs()
                 if a not in ("respawn", "respawn_delay", "output")]
        attrs.append(("test-name", self.test_name))
        if self.retry:
            attrs.append(("retry", str(self.retry)))
        if self.time_limit != TEST_TIME_LIMIT_DEFAULT:
            attrs.append(("time-limit", self.time_limit))
        return attrs
