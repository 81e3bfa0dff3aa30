"""`executable`: run a process and supervise it (ROS 2's ExecuteProcess)."""

from __future__ import annotations

import os
from collections.abc import Sequence
from typing import Any

from launcher.description.action import Action
from launcher.description.actions.entries import NameValue
from launcher.description.actions.event_handlers import OnProcessExit, OnProcessStart
from launcher.description.actions.machine import (
    HERE,
    Placement,
    lookup,
    machine_attr,
    scoped,
)
from launcher.description.actions.shutdown import Shutdown
from launcher.description.command_line import join_command, split_command
from launcher.description.condition import entry_applies, if_attr, unless_attr
from launcher.description.fields import Kind, attr, resolve
from launcher.description.registry import action
from launcher.description.substitution import Substitution, Text_, perform_text, to_text
from launcher.errors import ExecutionError, did_you_mean
from launcher.records import dataclass, field
from launcher.runtime.context import LaunchContext
from launcher.runtime.machine import Machine, RemoteStart
from launcher.runtime.process import ProcessSpec

# output mode -> (where stdout goes, where stderr goes), as in ROS 2
OUTPUT_MODES = {
    "screen": ({"screen"}, {"screen"}),
    "log": ({"log"}, {"log", "screen"}),
    "both": ({"log", "screen"}, {"log", "screen"}),
    "own_log": ({"own_log"}, {"own_log"}),
    "full": ({"screen", "log", "own_log"}, {"screen", "log", "own_log"}),
}


@dataclass(eq=False)
class EnvEntry(NameValue):
    """An environment variable of the process."""

    only_if: Any = if_attr()
    only_unless: Any = unless_attr()


@action("executable")
@dataclass(kw_only=True, eq=False)
class ExecuteProcess(Action):
    completes_later = True  # (when its process ends: the process table says so)
    cmd: Any = attr(Kind.COMMAND, required=True,
                    doc="The command line; split like a shell, substitutions kept whole.")
    args: Any = attr(Kind.COMMAND, doc="More arguments, appended to cmd.")
    cwd: Text_ | None = attr(Kind.TEXT, doc="Working directory (must exist).")
    name: Text_ | None = attr(Kind.TEXT, doc="Label base for output; default: the program.")
    prefix: Any = attr(Kind.COMMAND, name="launch-prefix", aliases=("launch_prefix",),
                       doc="Words put before the command (e.g. 'gdb -ex run --args').")
    output: Any = attr(Kind.TEXT, choices=tuple(OUTPUT_MODES),
                       doc="screen, log (default), both, own_log or full.")
    shell: Any = attr(Kind.BOOL, False, doc="Run the command line through /bin/sh.")
    emulate_tty: Any = attr(Kind.BOOL, False, doc="Give the process a pseudo-terminal.")
    sigterm_timeout: Any = attr(Kind.FLOAT, 5.0, minimum=0,
                                doc="Seconds after SIGINT before SIGTERM.")
    sigkill_timeout: Any = attr(Kind.FLOAT, 5.0, minimum=0,
                                doc="Seconds after SIGTERM before SIGKILL.")
    respawn: Any = attr(Kind.BOOL, False, doc="Start it again whenever it exits.")
    respawn_delay: Any = attr(Kind.FLOAT, 0.0, minimum=0, doc="Seconds before a respawn.")
    respawn_max_retries: Any = attr(Kind.INT, -1, minimum=-1,
                                    doc="Respawns allowed; -1 means no limit.")
    on_exit: Any = attr(Kind.ACTIONS,
                        doc="'shutdown', or actions to run each time the process exits.")
    on_start: Any = attr(Kind.ACTIONS, doc="Actions to run each time the process starts.")
    additional_env: list[EnvEntry] = attr(Kind.ENTRIES, name="env", entry=EnvEntry,
                                          doc="Environment variables for this process.")
    machine: Any = machine_attr("The machine it runs on, one a <machine> declares "
                                "(roslaunch's machine=; in ROS 2 files launcher's extension); "
                                "default: its group's, else this host.")
    # the Python API's env=: the whole environment instead of the launch's (as ROS 2's)
    env: dict[Any, Any] | None = field(default=None, repr=False)
    # the Python API's cached_output=: keep the output for get_stdout()/get_stderr() (tests)
    cached_output: bool = field(default=False, repr=False)

    def __post_init__(self) -> None:
        if self.cmd is not None and not isinstance(self.cmd, str | list | tuple | Substitution):
            raise TypeError(f"ExecuteProcess(cmd={self.cmd!r:.40}): expected the command as a "
                            f"list of words (text or substitutions) or one text, got "
                            f"{type(self.cmd).__name__}")
        super().__post_init__()
        if isinstance(self.on_exit, str):
            if self.on_exit.strip() != "shutdown":
                raise ValueError(f"on_exit: expected 'shutdown' or a list of actions, "
                                 f"got '{self.on_exit}'")
            self.on_exit = [Shutdown(reason=to_text("a process with on_exit=shutdown exited"))]
        for name in ("on_exit", "on_start"):  # ROS 2 also takes one action: on_exit=Shutdown()
            if isinstance(getattr(self, name), Action):
                setattr(self, name, [getattr(self, name)])
        env = self.additional_env
        pairs = env.items() if isinstance(env, dict) else env
        self.additional_env = [e if isinstance(e, EnvEntry) else EnvEntry(to_text(e[0]),
                                                                          to_text(e[1]))
                               for e in pairs]

    # --- building the process -------------------------------------------------------------
    def _words(self, context: LaunchContext, value: Any) -> list[str]:
        if value is None:
            return []
        if isinstance(value, list):
            return [perform_text(context, to_text(v)) for v in value]
        return split_command(context, to_text(value))

    def launch_prefix(self, context: LaunchContext) -> list[str]:
        """`--launch-prefix` of the run, then this action's own `launch-prefix` (without
        one, the launch configuration `launch-prefix`, as launch has it)."""
        own = self.prefix if self.prefix is not None else \
            context.configurations.get("launch-prefix") or None
        return self.run_prefix(context) + self._words(context, own)

    @staticmethod
    def run_prefix(context: LaunchContext) -> list[str]:
        """`--launch-prefix` of the run, as words."""
        run_prefix = getattr(context.service, "launch_prefix", "") or ""
        return split_command(context, to_text(run_prefix)) if run_prefix else []

    def command_line(self, context: LaunchContext) -> list[str]:
        prefix = self.launch_prefix(context)
        if resolve(context, self.shell, Kind.BOOL, "shell"):
            parts = [join_command(context, to_text(self.cmd))] if not isinstance(
                self.cmd, list) else self._words(context, self.cmd)
            parts += self._words(context, self.args)
            return [*prefix, "/bin/sh", "-c", " ".join(parts)]
        return [*prefix, *self._words(context, self.cmd), *self._words(context, self.args)]

    def environment(self, context: LaunchContext) -> dict[str, str]:
        env = dict(context.environment) if self.env is None else {
            perform_text(context, to_text(k)): perform_text(context, to_text(v))
            for k, v in self.env.items()}
        for entry in self.additional_env:
            if entry_applies(context, entry):
                env[perform_text(context, entry.name)] = perform_text(context, entry.value)
        return env

    def spec(self, context: LaunchContext) -> ProcessSpec:
        argv = self.command_line(context)
        base = perform_text(context, self.name) if self.name is not None else \
            os.path.basename(argv[0]) if argv else ""
        machine = self.machine_of(context)
        placement = Placement(machine, None if machine is None or machine.local else
                              RemoteStart(None, None))  # (its command, run there as is)
        return self.process_spec(context, argv, self.environment(context), base,
                                 placement=placement)

    def machine_of(self, context: LaunchContext) -> Machine | None:
        """The machine it runs on: the one it names, else its scope's (None: here)."""
        if self.machine is not None:
            return lookup(context, perform_text(context, self.machine))
        return scoped(context)

    def process_spec(self, context: LaunchContext, argv: list[str], env: dict[str, str],
                     base: str, cwd: str | None = None,
                     placement: Placement = HERE) -> ProcessSpec:
        """The process to start, from its command line, environment and label base (and its
        working folder, when the action decides it otherwise than by `cwd`; and where it
        runs: a process on another host is checked there, not here)."""
        if not argv:
            raise ExecutionError("the command line is empty")
        if cwd is None and self.cwd is not None:
            cwd = perform_text(context, self.cwd)
        remote = placement.remote is not None
        program = argv[0] if remote else check_runnable(argv[0], env, cwd)
        mode = resolve(context, self.output or "log", Kind.TEXT, "output",
                       _field_spec(self, "output"))
        stdout_to, stderr_to = OUTPUT_MODES[mode]

        def num(field: str, kind: Kind) -> Any:
            return resolve(context, getattr(self, field), kind, field, _field_spec(self, field))

        return ProcessSpec(
            label=context.service.next_label(base), argv=argv, env=env, cwd=cwd,
            joins_graph=remote or _may_join_graph(program),
            emulate_tty=resolve(context, self.emulate_tty, Kind.BOOL, "emulate_tty"),
            stdout_to=frozenset(stdout_to), stderr_to=frozenset(stderr_to),
            sigterm_timeout=num("sigterm_timeout", Kind.FLOAT),
            sigkill_timeout=num("sigkill_timeout", Kind.FLOAT),
            respawn=resolve(context, self.respawn, Kind.BOOL, "respawn"),
            respawn_delay=num("respawn_delay", Kind.FLOAT),
            respawn_max_retries=num("respawn_max_retries", Kind.INT), origin=self,
            machine=placement.machine, remote=placement.remote,
        )

    def execute(self, context: LaunchContext) -> Sequence[Action] | None:
        if context.service is None:
            return None
        spec = self.spec(context)
        self._register_reactions(context, spec.label)
        if self.cached_output:
            self._cache = {"stdout": [], "stderr": []}
            context.service.register_handler(_LabelHandler(spec.label, _OutputCache(self._cache)))
        try:
            context.service.start_process(spec, lambda process: self._spawned(context, process))
        except OSError as exc:
            raise ExecutionError(f"cannot start '{spec.program}': {exc.strerror or exc}") from None
        return None

    def _spawned(self, context: LaunchContext, process: Any) -> None:
        self._process = process
        self.started(context, process)

    # --- what the Python API's users read (launch tests) ----------------------------------
    @property
    def process_details(self) -> dict[str, Any] | None:
        """Its latest process: name (its label), cmd, cwd, env and pid; None before one
        starts."""
        process = getattr(self, "_process", None)
        if process is None:
            return None
        spec = process.spec
        return {"name": process.label, "cmd": list(spec.argv), "cwd": spec.cwd,
                "env": dict(spec.env), "pid": process.pid}

    @property
    def return_code(self) -> int | None:
        """The exit status of its latest process; None while that runs, or before it starts."""
        process = getattr(self, "_process", None)
        return None if process is None else process.returncode

    def get_stdout(self) -> str:
        """All its processes have written to stdout (with `cached_output=True`)."""
        return self._cached("stdout")

    def get_stderr(self) -> str:
        """All its processes have written to stderr (with `cached_output=True`)."""
        return self._cached("stderr")

    def _cached(self, stream: str) -> str:
        if not self.cached_output:
            raise RuntimeError(f"cached output must be true to be able to get {stream}: "
                               "ExecuteProcess(..., cached_output=True)")
        return "".join(getattr(self, "_cache", {}).get(stream, ()))

    def started(self, context: LaunchContext, process: Any) -> None:
        """Called once the process is spawned (a container then loads its nodes): at once, or
        when the graph's parameters are set (LaunchService.hold_graph)."""

    def _register_reactions(self, context: LaunchContext, label: str) -> None:
        for handler_type, reaction in ((OnProcessExit, self.on_exit),
                                       (OnProcessStart, self.on_start)):
            if not reaction:
                continue
            handler = _LabelHandler(label, handler_type(**{
                "on_exit" if handler_type is OnProcessExit else "on_start": reaction}))
            handler.inner.snapshot = context.snapshot()
            context.service.register_handler(handler)

    def sub_actions(self) -> Sequence[Action]:
        return [*(self.on_start if isinstance(self.on_start, list) else []),
                *(self.on_exit if isinstance(self.on_exit, list) else [])]


@dataclass
class _LabelHandler:
    """Match the events of one started process (one execution of the action)."""

    label: str
    inner: Any

    def matches(self, event: Any) -> bool:
        return self.inner.matches(event) and getattr(event, "process_name", None) == self.label

    def handle(self, event: Any, context: LaunchContext) -> Any:
        return self.inner.handle(event, context)


@dataclass
class _OutputCache:
    """Keeps a process's output lines (an action's `cached_output`)."""

    lines: dict[str, list[str]]

    def matches(self, event: Any) -> bool:
        return getattr(event, "stream", None) in self.lines

    def handle(self, event: Any, context: LaunchContext) -> None:
        self.lines[event.stream].append(event.line + "\n")


def _field_spec(obj: Any, name: str) -> Any:
    return type(obj).__dataclass_fields__[name].metadata["launch"]


SYSTEM_FOLDERS = ("/bin", "/sbin", "/usr/bin", "/usr/sbin", "/usr/local/bin", "/usr/local/sbin")


def _may_join_graph(program: str) -> bool:
    """Whether the program (its path) may be a ROS node: anything but a system tool (sleep,
    sh, …) that is not Python. A wrong yes only starts the graph's router a little early."""
    folder, name = os.path.split(os.path.realpath(program))
    return folder not in SYSTEM_FOLDERS or name.startswith("python")


def check_runnable(program: str, env: dict[str, str], cwd: str | None) -> str:
    """The program's path; clear errors for the usual mistakes, before trying to spawn."""
    if cwd is not None and not os.path.isdir(cwd):
        raise ExecutionError(f"cwd '{cwd}' does not exist or is not a folder")
    if "/" in program:
        path = program if os.path.isabs(program) or cwd is None else os.path.join(cwd, program)
        if not os.path.exists(path):
            raise ExecutionError(f"executable '{program}' does not exist")
        if not os.access(path, os.X_OK) or os.path.isdir(path):
            raise ExecutionError(f"'{program}' is not executable")
        return path
    search = env.get("PATH", os.defpath)
    found = _which(program, search)
    if found is None:
        raise ExecutionError(f"executable '{program}' not found on PATH"
                             f"{did_you_mean(program, _programs_on(search))}")
    return found


def _which(program: str, search: str) -> str | None:
    """shutil.which for a bare name (shutil is a good part of a launch's start-up imports)."""
    for folder in search.split(os.pathsep):
        path = os.path.join(folder or os.curdir, program)
        if os.access(path, os.X_OK) and not os.path.isdir(path):
            return path
    return None


def _programs_on(search: str) -> set[str]:
    names: set[str] = set()
    for folder in search.split(os.pathsep):
        try:
            names.update(os.listdir(folder))
        except OSError:
            continue
    return names
