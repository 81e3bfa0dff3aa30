"""The launch context: what substitutions read and actions change while a launch runs.

Configurations (launch arguments and `let`s) and the environment for new processes live in a
stack of scopes that `group` and scoped includes push and pop. Loop variables live in their own
stack, so that a loop does not scope the `let`s in its body (as in ROS 2).
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable, Iterator, Mapping, MutableMapping
from contextlib import contextmanager
from pathlib import Path
from typing import Any, NamedTuple, Protocol, runtime_checkable

from launcher.records import dataclass
from launcher.runtime.files_read import FilesRead
from launcher.runtime.machine import Machine


@dataclass
class Scope:
    configurations: dict[str, str]
    environment: dict[str, str]

    def copy(self) -> Scope:
        return Scope(dict(self.configurations), dict(self.environment))


class Locals(dict):
    """Context locals: a dict whose keys read as attributes too (`context.locals.event`)."""

    def __getattr__(self, name: str) -> Any:
        try:
            return self[name]
        except KeyError:
            raise AttributeError(f"context.locals has no '{name}'") from None


class Snapshot(NamedTuple):
    """A frozen copy of the context, to run deferred actions (timers, handlers) in later."""

    scope: Scope
    locals: dict[str, str]
    file: Path | None


@runtime_checkable
class Runtime(Protocol):
    """What actions use of the service that runs a launch (the LaunchService, or a test's
    recording fake)."""

    launch_prefix: str
    shutting_down: bool
    coroutines: Any  # the launch's asyncio loop and its coroutines (runtime/coroutines.py)

    def next_label(self, base: str) -> str: ...

    def start_process(self, spec: Any, started: Callable[[Any], None] | None = None) -> None:
        ...

    def hold_graph(self) -> None: ...

    def register_handler(self, handler: Any) -> None: ...

    def would_handle(self, event: Any) -> bool: ...

    def emit(self, event: Any) -> None: ...

    def watch_lifecycle(self, node: str, origin: Any) -> None: ...

    def change_states(self, node: str, transitions: list[int], where: Any) -> None: ...

    def add_timer(self, period: float, callback: Callable[[], None],
                  cancel_on_shutdown: bool = True) -> Any: ...

    def schedule(self, actions: Any) -> None: ...

    def shutdown(self, reason: str) -> None: ...

    def log(self, level: str, source: str, message: str) -> None: ...

    def report(self, exc: Any) -> None: ...


class LaunchContext:
    """State shared by the actions of one launch.

    `service` is the runtime that runs processes and timers; it is None when a launch file is
    only inspected (`--show-args`, `--print`), and actions that need it must check.
    `load_description` turns a launch file path into a description (the frontend's loader);
    `packages` is the package index node actions and `$(find-pkg-…)` look in;
    `parse_text(text, file, roslaunch=False)` reads the substitutions in a file's text (a
    params file with allow_substs; roslaunch's rosparam with subst_value).
    """

    def __init__(
        self,
        environment: Mapping[str, str] | None = None,
        configurations: Mapping[str, str] | None = None,
        service: Runtime | None = None,
        log_dir: Path | None = None,
        load_description: Callable[[Path], Any] | None = None,
        packages: Any = None,
        parse_text: Callable[..., Any] | None = None,
        *,
        argv: list[str] | None = None,
        noninteractive: bool = False,
    ) -> None:
        self._in_process = False  # (see process_environment)
        env = dict(os.environ if environment is None else environment)
        self.initial_environment = dict(env)
        self._scopes = [Scope(dict(configurations or {}), env)]
        self._locals: list[Locals] = [Locals()]
        self._saved: list[tuple[str, dict[str, str]]] = []  # Push/Pop Environment, …
        self.argv = list(argv or [])  # launch's LaunchContext.argv (the LaunchService's)
        self.noninteractive = noninteractive
        self.files = FilesRead(lambda: self.locals)  # the launch files being read
        self.service = service
        self.log_dir = log_dir
        self.anonymous_names: dict[str, str] = {}
        self.load_description = load_description
        self.packages = packages
        self.parse_text = parse_text
        self.node_names: dict[str, Any] = {}  # fully qualified node name -> where declared
        self.lifecycle_nodes: list[Any] = []  # lifecycle_node actions started, in order
        self.declared: set[str] = set()  # the launch arguments an `arg` has declared
        # ROS 1 parameters for the graph's parameter server (full names), and whether its
        # start is queued (it comes once everything queued now has been visited)
        self.graph_parameters: dict[str, Any] = {}
        # roslaunch's `rosparam delete|dump` ([command, name(, file)]), run before they are set
        self.graph_commands: list[list[str]] = []
        self.machines: dict[str, Machine] = {}  # the machines declared so far, by name
        # roslaunch's <machine default="true">: for its later nodes without machine=, in
        # document order whatever the group or include (not scoped: xmlloader._recurse_load)
        self.default_machine: Machine | None = None
        # what is checked once the launch files being read are read (each may raise a
        # LaunchError: the launch fails before the processes waiting for that start)
        self.loaded_checks: list[Callable[[], None]] = []
        self.graph_parameters_file: Path | None = None  # where they will be written

    # --- scopes -------------------------------------------------------------------------
    @property
    def scope(self) -> Scope:
        return self._scopes[-1]

    @property
    def configurations(self) -> dict[str, str]:
        return self.scope.configurations

    @property
    def environment(self) -> Any:
        """The environment new processes get: os.environ itself while code of the user's
        runs (launch's context.environment is the process's), else the scope's."""
        return os.environ if self._in_process else self.scope.environment

    @contextmanager
    def process_environment(self) -> Iterator[None]:
        """While code of the user's runs (an OpaqueFunction, an action or a handler of
        theirs), os.environ is the launch's environment, as in launch, where the two are one:
        what the code reads there is what SetEnvironmentVariable set, and what it sets in
        either is kept. launcher's own os.environ comes back after."""
        if self._in_process:
            yield
            return
        own = dict(os.environ)
        _replace(os.environ, self.scope.environment)
        self._in_process = True
        try:
            yield
        finally:
            self._in_process = False
            _replace(self.scope.environment, os.environ)
            _replace(os.environ, own)

    def push_scope(self, forwarding: bool = True, keep: Mapping[str, str] | None = None) -> None:
        scope = self.scope.copy()
        if not forwarding:
            scope.configurations = {}
        scope.configurations.update(keep or {})
        self._scopes.append(scope)

    def pop_scope(self) -> None:
        if len(self._scopes) == 1:
            raise RuntimeError("pop_scope without a matching push_scope")
        self._scopes.pop()

    def push_environment(self) -> None:
        """Save the environment (launch's PushEnvironment); pop_environment restores it."""
        self._saved.append(("environment", dict(self.environment)))

    def pop_environment(self) -> None:
        self._restore("environment")

    def push_configurations(self) -> None:
        """Save the configurations (launch's PushLaunchConfigurations)."""
        self._saved.append(("configurations", dict(self.configurations)))

    def pop_configurations(self) -> None:
        self._restore("configurations")

    def _restore(self, what: str) -> None:
        for index in range(len(self._saved) - 1, -1, -1):
            if self._saved[index][0] == what:
                saved = self._saved.pop(index)[1]
                current = getattr(self.scope, what)
                current.clear()
                current.update(saved)
                return
        kind = "Environment" if what == "environment" else "LaunchConfigurations"
        raise RuntimeError(f"Pop{kind} without a Push{kind} before it")

    # --- loop variables, and launch's context locals ------------------------------------
    @property
    def locals(self) -> Locals:
        """launch's `context.locals` (`context.locals.event` in an event handler's actions),
        and the loop variables of ForEach and ForLoop."""
        return self._locals[-1]

    def extend_locals(self, values: Mapping[str, Any]) -> None:
        self._locals[-1].update(values)

    def extend_globals(self, values: Mapping[str, Any]) -> None:
        for frame in self._locals:
            for key, value in values.items():
                frame.setdefault(key, value)

    def get_locals_as_dict(self) -> dict[str, Any]:
        return dict(self.locals)

    def push_locals(self, values: Mapping[str, str] | None = None) -> None:
        self._locals.append(Locals({**self.locals, **(values or {})}))

    def pop_locals(self) -> None:
        self._locals.pop()

    # --- launch's LaunchContext API, for actions and handlers of the user's own ----------
    @property
    def launch_configurations(self) -> dict[str, str]:
        return self.configurations

    def perform_substitution(self, substitution: Any) -> str:
        return substitution.perform(self)

    @property
    def asyncio_loop(self) -> Any:
        """launch's context.asyncio_loop: the launch's asyncio loop, on a thread of its own
        (None for a launch only inspected)."""
        coroutines = None if self.service is None else self.service.coroutines
        return None if coroutines is None else coroutines.asyncio_loop

    @property
    def is_shutdown(self) -> bool:
        return self.service is not None and self.service.shutting_down

    def emit_event(self, event: Any) -> None:
        """Hand an event to the launch's handlers (after the action being visited)."""
        if self.service is not None:
            self.service.emit(event)

    emit_event_sync = emit_event

    def would_handle_event(self, event: Any) -> bool:
        return self.service is not None and self.service.would_handle(event)

    def register_event_handler(self, event_handler: Any, append: bool = False) -> None:
        if self.service is not None:
            self.service.register_handler(event_handler)

    def unregister_event_handler(self, event_handler: Any) -> None:
        if self.service is not None:
            self.service.unregister_handler(event_handler)

    def log(self, level: str, message: str) -> None:
        """A message from an action or substitution: to the run's output and log."""
        if self.service is not None:
            self.service.log(level, "launch", message)
        else:
            sys.stderr.write(f"[{level}] [launch]: {message}\n")

    # --- deferred work ------------------------------------------------------------------
    def snapshot(self) -> Snapshot:
        return Snapshot(self.scope.copy(), dict(self.locals), self.files.current)

    def enter(self, snapshot: Snapshot) -> None:
        """Push a scope, loop variables and file equal to the snapshot's (undo with leave)."""
        self._scopes.append(snapshot.scope.copy())
        self._locals.append(Locals(snapshot.locals))
        self.files.enter(snapshot.file)

    def leave(self) -> None:
        self._scopes.pop()
        self._locals.pop()
        self.files.leave()


def _replace(target: MutableMapping[str, str], source: Mapping[str, str]) -> None:
    """Make `target` hold what `source` holds, touching only what differs (os.environ's
    writes are putenv calls)."""
    for key in [key for key in target if key not in source]:
        del target[key]
    for key, value in source.items():
        if target.get(key) != value:
            target[key] = value
