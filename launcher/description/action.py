"""The action base class and the launch description that holds actions."""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from pathlib import Path

from launcher.description.condition import Condition
from launcher.description.fields import normalize
from launcher.errors import LaunchError, Location
from launcher.records import dataclass, field
from launcher.runtime.context import LaunchContext, Snapshot


@dataclass(kw_only=True, eq=False)
class Action:
    """Something a launch does. `visit` checks the condition, then runs `execute`.

    `execute` returns the actions to visit next (depth first, before later siblings), or None.
    """

    condition: Condition | None = field(default=None, repr=False)
    where: Location | None = field(default=None, repr=False, compare=False)
    tags = ()  # set by @action

    def __post_init__(self) -> None:
        normalize(self)

    def visit(self, context: LaunchContext) -> Sequence[Action] | None:
        try:
            if self.condition is not None and not self.condition.evaluate(context):
                return None
            return self.execute(context)
        except LaunchError as exc:
            raise exc.at(self.where) from None

    def execute(self, context: LaunchContext) -> Sequence[Action] | None:
        raise NotImplementedError

    def sub_actions(self) -> Sequence[Action]:
        """Actions nested in this one, for static walks (`--print`, `--show-args`)."""
        return ()


@dataclass(kw_only=True, eq=False)
class LaunchDescription(Action):
    """A list of actions, as a launch file gives them; `file` is where they came from."""

    actions: list[Action] = field(default_factory=list)
    file: Path | None = None

    def __init__(self, actions: Iterable[Action] = (), *, file: Path | None = None,
                 where: Location | None = None) -> None:
        self.actions = list(actions)
        self.file = file
        self.where = where
        self.condition = None

    def add_action(self, action: Action) -> None:
        self.actions.append(action)

    def execute(self, context: LaunchContext) -> Sequence[Action]:
        if self.file is None:
            return self.actions
        return [_PushFile(self.file), *self.actions, _PopFile()]

    def sub_actions(self) -> Sequence[Action]:
        return self.actions


class _Internal(Action):
    """Bookkeeping steps the actions above expand into (plain classes: no generated code)."""

    def __init__(self) -> None:
        self.condition, self.where = None, None


class _PushFile(_Internal):
    def __init__(self, path: Path | None) -> None:
        super().__init__()
        self.path = path

    def execute(self, context: LaunchContext) -> None:
        context.push_file(self.path)


class _PopFile(_Internal):
    def execute(self, context: LaunchContext) -> None:
        context.pop_file()


class PushScope(_Internal):
    def __init__(self, forwarding: bool = True, keep: dict[str, str] | None = None) -> None:
        super().__init__()
        self.forwarding, self.keep = forwarding, keep or {}

    def execute(self, context: LaunchContext) -> None:
        context.push_scope(self.forwarding, self.keep)


class PopScope(_Internal):
    """The end of a scope; the configurations named in `carry` keep the values they had inside
    (roslaunch's parameters outlive the file that set them)."""

    def __init__(self, carry: tuple[str, ...] = ()) -> None:
        super().__init__()
        self.carry = carry

    def execute(self, context: LaunchContext) -> None:
        kept = {k: context.configurations[k] for k in self.carry if k in context.configurations}
        context.pop_scope()
        context.configurations.update(kept)


class Replay(_Internal):
    """Run actions later in the context they were written in (timers, event handlers)."""

    def __init__(self, snapshot: Snapshot, actions: Sequence[Action]) -> None:
        super().__init__()
        self.snapshot, self.actions = snapshot, actions

    def execute(self, context: LaunchContext) -> Sequence[Action]:
        context.enter(self.snapshot)
        return [*self.actions, _Leave()]


class _Leave(_Internal):
    def execute(self, context: LaunchContext) -> None:
        context.leave()


class PushLocals(_Internal):
    def __init__(self, values: dict[str, str]) -> None:
        super().__init__()
        self.values = values

    def execute(self, context: LaunchContext) -> None:
        context.push_locals(self.values)


class PopLocals(_Internal):
    def execute(self, context: LaunchContext) -> None:
        context.pop_locals()

