"""Machines: `machine` (launcher's extension of ROS 2 files), `roslaunch_machine` (roslaunch's
`<machine>`), `PushMachine` (the machine of the processes after it in its scope, as
push_ros_namespace scopes a namespace), and how a process finds the machine it runs on.

A machine is declared before a ROS 2 file's processes name it (as `let` before `$(var)`); a
ROS 1 node may name one declared anywhere in the launch, as roslaunch assigns machines once
every file is read (node.py places it then).
"""

from __future__ import annotations

from typing import Any, NamedTuple

from launcher.description.action import Action
from launcher.description.fields import Attr, Kind, attr, resolve
from launcher.description.registry import EXTENSION, action
from launcher.description.substitution import perform_text
from launcher.errors import ExecutionError, did_you_mean
from launcher.records import dataclass, field
from launcher.runtime.context import LaunchContext
from launcher.runtime.machine import DEFAULT_TIMEOUT, Machine, RemoteStart

SCOPED = "<machine>"  # the configuration PushMachine sets: the name of its scope's machine
DEFAULTS = ("true", "false", "never")  # roslaunch's default=; never: false (it is not read)
SETTINGS = (("address", "address"), ("user", "user"), ("ssh-port", "ssh_port"),
            ("env-loader", "env_loader"), ("timeout", "timeout"))


class Placement(NamedTuple):
    """Where a process runs: on `machine` (None: here), started there as `remote` says when
    that is another host (None: here, as any process)."""

    machine: Machine | None = None
    remote: RemoteStart | None = None


HERE = Placement()


def machine_attr(doc: str) -> Any:
    """The `machine` field of a process or group: launcher's extension in ROS 2 files."""
    return field(default=None, metadata={"launch": Attr(Kind.TEXT, doc=doc), EXTENSION: True})


def password_refusal(login: str) -> str:
    return ("<machine password=…>: launcher logs in with OpenSSH, which takes no password "
            f"from a program; use key-based login (ssh-keygen; ssh-copy-id {login}) and an "
            "ssh-agent (ssh-add), then remove password=")


@dataclass(kw_only=True, eq=False)
class _Declaration(Action):
    """What both syntaxes of `<machine>` declare."""

    name: Any = attr(Kind.TEXT, required=True, doc="The machine's name, which processes give "
                                                   "as machine=.")
    address: Any = attr(Kind.TEXT, required=True, doc="Its host name or address, as ssh "
                                                      "takes it (a Host of ~/.ssh/config too).")
    user: Any = attr(Kind.TEXT, doc="The user to log in as (default: ssh's).")
    ssh_port: Any = attr(Kind.INT, name="ssh-port", aliases=("ssh_port",), minimum=1,
                         maximum=65535, doc="The port sshd listens on (default: ssh's).")
    env_loader: Any = attr(Kind.TEXT, name="env-loader", aliases=("env_loader",),
                           doc="A script on that host that sets the environment up and runs "
                               "its arguments (`exec \"$@\"`).")
    timeout: Any = attr(Kind.FLOAT, DEFAULT_TIMEOUT, above=0,
                        doc="Seconds the connection may take to be ready.")
    password: Any = attr(Kind.TEXT, doc="Refused: OpenSSH takes no password from a program "
                                        "(key-based login and ssh-agent instead).")

    def machine(self, context: LaunchContext) -> Machine:
        """The machine as declared, its substitutions performed and its values checked."""
        address = _optional(context, self.address)
        user = _optional(context, self.user)
        if self.password is not None:
            raise ExecutionError(password_refusal(f"{user}@{address}" if user else
                                                  address or "HOST"))
        if address is None:
            raise ExecutionError("<machine address=…>: expected a host name or address, "
                                 "got ''")
        return Machine(perform_text(context, self.name), address, user,
                       self._number(context, "ssh_port", Kind.INT),
                       _optional(context, self.env_loader),
                       self._number(context, "timeout", Kind.FLOAT),
                       str(self.where or self.made_at or ""))

    def _number(self, context: LaunchContext, name: str, kind: Kind) -> Any:
        spec = type(self).__dataclass_fields__[name].metadata["launch"]
        return resolve(context, getattr(self, name), kind, spec.name or name, spec)


@action("machine", extension=True)
@dataclass(kw_only=True, eq=False)
class DeclareMachine(_Declaration):
    """A host that processes may run on, over ssh (launcher's extension of ROS 2 files:
    a file says so with `<launch extensions="launcher">`, in YAML `extensions: [launcher]`
    beside `launch:`). A machine whose address is this host runs its processes here."""

    def execute(self, context: LaunchContext) -> None:
        declare(context, self.machine(context))


@action("roslaunch_machine")
@dataclass(kw_only=True, eq=False)
class RoslaunchMachine(_Declaration):
    """roslaunch's `<machine>` (a ROS 1 file's): a host its nodes may name with machine=."""

    default: Any = attr(Kind.TEXT, doc="true: the machine of the nodes after it without "
                                       "machine=, across groups and includes (roslaunch's); "
                                       "false or never: not.")

    def execute(self, context: LaunchContext) -> None:
        word = perform_text(context, self.default).strip().lower() \
            if self.default is not None else "false"
        if word not in DEFAULTS:
            raise ExecutionError(f"<machine default='{word}'>: expected true, false or never"
                                 f"{did_you_mean(word, DEFAULTS)}")
        machine = declare(context, self.machine(context))
        if word == "true":  # (xmlloader._recurse_load: in document order, not scoped)
            context.default_machine = machine


@dataclass(kw_only=True, eq=False)
class PushMachine(Action):
    """The machine of the processes after it in its scope (a group's)."""

    name: Any = attr(Kind.TEXT, required=True, doc="A declared machine's name.")

    def execute(self, context: LaunchContext) -> None:
        name = perform_text(context, self.name)
        lookup(context, name)
        context.configurations[SCOPED] = name


def declare(context: LaunchContext, machine: Machine) -> Machine:
    """Add a machine to the launch's (roslaunch's config.add_machine: the same name again
    must say the same); the one declared under its name."""
    known = context.machines.setdefault(machine.name, machine)
    if known.key() != machine.key():
        differences = "; ".join(
            f"{label} {_shown(getattr(machine, key))} here, {_shown(getattr(known, key))} at "
            f"{known.where or 'the first declaration'}"
            for label, key in SETTINGS if getattr(machine, key) != getattr(known, key))
        raise ExecutionError(f"machine '{machine.name}' is declared twice with different "
                             f"settings: {differences} (a machine's name is one host)")
    return known


def lookup(context: LaunchContext, name: str) -> Machine:
    """The machine declared as `name`; an error with "did you mean" if none is."""
    machine = context.machines.get(name)
    if machine is None:
        raise ExecutionError(f"unknown machine '{name}'{did_you_mean(name, context.machines)}"
                             ": declare it with <machine name=… address=…/> (in a ROS 2 "
                             "file, before the processes that name it; in Python: "
                             "Machine(name=…, address=…))")
    return machine


def scoped(context: LaunchContext) -> Machine | None:
    """The machine PushMachine (a group's machine=) set for its scope, if any."""
    name = context.configurations.get(SCOPED)
    return lookup(context, name) if name else None


def params_files(*argvs: list[str]) -> tuple[str, ...]:
    """Every file given as `--params-file FILE` in these command lines, once each."""
    found: dict[str, None] = {}
    for argv in argvs:
        for flag, value in zip(argv, argv[1:], strict=False):
            if flag == "--params-file":
                found[value] = None
    return tuple(found)


def _optional(context: LaunchContext, value: Any) -> str | None:
    """Text, or None for a value not given or empty (roslaunch's `user or None`)."""
    return (perform_text(context, value).strip() or None) if value is not None else None


def _shown(value: Any) -> str:
    return "unset" if value is None else str(value)
