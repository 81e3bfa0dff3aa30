"""The action base class and the launch description that holds actions."""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from operator import attrgetter
from pathlib import Path
from typing import Any

from launcher.description import made_by_code
from launcher.description.condition import Condition
from launcher.description.fields import normalize
from launcher.errors import ExecutionError, LaunchError, Location
from launcher.records import dataclass, field
from launcher.runtime.context import LaunchContext, Snapshot
from launcher.runtime.events import ExecutionComplete


class LaunchDescriptionEntity:
    """launch.LaunchDescriptionEntity: what a launch description holds (actions, and
    descriptions themselves). `made_at`: where code of the user's made it, if it did."""

    made_at: Location | None = None
    condition: Condition | None = None
    where: Location | None = None
    tags: tuple[str, ...] = ()

    def __new__(cls, *args: Any, **kwargs: Any) -> Any:
        entity = super().__new__(cls)
        made_by_code.note(entity)
        return entity

    def visit(self, context: LaunchContext) -> Sequence[LaunchDescriptionEntity] | None:
        """The entities to visit next; a subclass of the user's says what it does here."""
        raise NotImplementedError

    def describe(self) -> str:
        """launch's: the object itself (a class of the user's may say more)."""
        return object.__repr__(self)

    def get_sub_entities(self) -> list[LaunchDescriptionEntity]:
        return []

    def sub_actions(self) -> Sequence[LaunchDescriptionEntity]:
        """Entities nested in this one, for static walks (`--print`, `--show-args`)."""
        return ()

    def describe_sub_entities(self) -> list[LaunchDescriptionEntity]:
        return self.get_sub_entities()

    def describe_conditional_sub_entities(self) -> list[tuple[str, list[Any]]]:
        return []

    def get_asyncio_future(self) -> None:
        return None


@dataclass(kw_only=True, eq=False)
class Action(LaunchDescriptionEntity):
    """Something a launch does. `visit` checks the condition, then runs `execute`.

    `execute` returns the actions to visit next (depth first, before later siblings), or None.
    """

    condition: Condition | None = field(default=None, repr=False)
    where: Location | None = field(default=None, repr=False, compare=False)
    tags = ()  # set by @action
    completes_later = False  # its ExecutionComplete comes when its work ends (a process's)

    def __post_init__(self) -> None:
        normalize(self)

    def visit(self, context: LaunchContext) -> Sequence[Action] | None:
        try:
            if self.condition is not None and not self.condition.evaluate(context):
                return None
            try:
                if type(self).__module__.startswith("launcher."):
                    return self.execute(context)
                with context.process_environment():  # an action of the user's own
                    return self.execute(context)
            finally:
                if not self.completes_later:
                    _completed(self, context)
        except LaunchError as exc:
            raise exc.at(self.where or self.made_at) from None
        except Exception as exc:  # code of the user's (an action's execute, a callback)
            place = made_by_code.place_of(exc)
            if place is None:
                raise  # launcher's own: the runtime reports it
            error = ExecutionError(f"{type(self).__name__} raised {type(exc).__name__}: {exc}",
                                   place)
            error.__cause__ = exc
            raise error from None

    def execute(self, context: LaunchContext) -> Sequence[Action] | None:
        raise NotImplementedError

    def get_sub_entities(self) -> list[LaunchDescriptionEntity]:
        return list(self.sub_actions())

    @staticmethod
    def parse(entity: Any, parser: Any) -> tuple[type, dict[str, Any]]:
        """launch's Action.parse: the `if` / `unless` of a frontend entity, as the keyword
        arguments of an action (what a custom action's own `parse` begins with)."""
        from launcher.description.condition import IfCondition, UnlessCondition

        given = entity.get_attr("if", optional=True)
        denied = entity.get_attr("unless", optional=True)
        if given is not None and denied is not None:
            raise RuntimeError("if and unless conditions can't be used simultaneously")
        kwargs: dict[str, Any] = {}
        if given is not None:
            kwargs["condition"] = IfCondition(parser.parse_substitution(given))
        elif denied is not None:
            kwargs["condition"] = UnlessCondition(parser.parse_substitution(denied))
        return Action, kwargs


def _completed(action: Action, context: LaunchContext) -> None:
    """launch's ExecutionComplete for an action done when executed, for the handlers that
    want it (made only when one does)."""
    if context.service is None:
        return
    event = ExecutionComplete(action=action)
    if context.would_handle_event(event):
        context.emit_event(event)


@dataclass(kw_only=True, eq=False)
class LaunchDescription(Action):
    """A list of actions, as a launch file gives them; `file` is where they came from."""

    actions: list[Action] = field(default_factory=list)
    file: Path | None = None

    def __init__(self, initial_entities: Iterable[Action] | None = None, *,
                 deprecated_reason: str | None = None, file: Path | None = None,
                 where: Location | None = None) -> None:
        self.actions = list(initial_entities or ())
        self.deprecated_reason = deprecated_reason
        self.file = file
        self.where = where
        self.condition = None

    entities = property(attrgetter("actions"))

    def __str__(self) -> str:  # (launch's: the object, not its contents)
        return object.__repr__(self)

    @property
    def deprecated(self) -> bool:
        return self.deprecated_reason is not None

    def add_action(self, action: Action) -> None:
        self.actions.append(action)

    def add_entity(self, entity: Action) -> None:
        self.actions.append(entity)

    def get_launch_arguments(self, conditional_inclusion: bool = False) -> list[Action]:
        """The DeclareLaunchArgument actions in it and in what it holds statically."""
        found, todo = [], list(self.actions)
        while todo:
            entity = todo.pop(0)
            if "arg" in entity.tags:  # (DeclareLaunchArgument: the `arg` tag's action)
                found.append(entity)
            elif isinstance(entity, Action):
                todo[:0] = list(entity.sub_actions())
        return found

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
        context.files.push(self.path)


class _PopFile(_Internal):
    def execute(self, context: LaunchContext) -> None:
        context.files.pop()


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

