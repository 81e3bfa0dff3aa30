"""Event handlers, as launch has them: run actions when a process starts, exits or prints, an
action completes, or the launch shuts down.

The Python API's `RegisterEventHandler(OnProcessExit(target_action=…, on_exit=[…]))`, a
user's own `EventHandler(matcher=…, entities=…)`, and the frontends' `on_exit` / `on_start`
children of `executable` and `node` all end up here. Handler actions run in the scope in
which the handler was registered; `context.locals.event` is the event they answer.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

from launcher.description.action import Action, LaunchDescriptionEntity, Replay
from launcher.records import dataclass
from launcher.runtime import events
from launcher.runtime.context import LaunchContext, Snapshot

Reaction = Sequence[Action] | Callable[..., Sequence[Action] | Action | None]


class BaseEventHandler:
    """launch.event_handler.BaseEventHandler: `matcher(event)` picks the events;
    `handle_once` unregisters it after the first."""

    snapshot: Snapshot | None = None  # the scope it was registered in
    handler_description: str | None = None  # (a subclass says what it answers, and when)
    matcher_description: str | None = None

    def __init__(self, *, matcher: Callable[[Any], bool], handle_once: bool = False) -> None:
        self.__matcher = matcher
        self.__handle_once = handle_once

    @property
    def handle_once(self) -> bool:
        return self.__handle_once

    def matches(self, event: Any) -> bool:
        return bool(self.__matcher(event))

    def describe(self) -> tuple[str, list[Any]]:
        return (f"{type(self).__name__}(matcher='{self.matcher_description}', "
                f"handler='{self.handler_description}', handle_once={self.handle_once})", [])

    def reaction(self, event: Any, context: LaunchContext) -> Any:
        """The entities (or None) this handler answers `event` with."""
        return None

    def handle(self, event: Any, context: LaunchContext) -> Sequence[Action] | None:
        if self.handle_once:
            context.unregister_event_handler(self)
        snapshot = self.snapshot or context.snapshot()
        context.enter(snapshot)
        try:
            context.extend_locals({"event": event})
            with context.process_environment():
                actions = _entities(self.reaction(event, context))
        finally:
            context.leave()
        if not actions:
            return None
        return [Replay(snapshot=snapshot._replace(locals={**snapshot.locals, "event": event}),
                       actions=actions)]


class EventHandler(BaseEventHandler):
    """launch.EventHandler: `entities` for every event `matcher` picks."""

    def __init__(self, *, matcher: Callable[[Any], bool], entities: Any = None,
                 handle_once: bool = False) -> None:
        super().__init__(matcher=matcher, handle_once=handle_once)
        self.__entities = entities

    @property
    def entities(self) -> Any:
        return self.__entities

    def reaction(self, event: Any, context: LaunchContext) -> Any:
        return self.__entities


class OnActionEventBase(BaseEventHandler):
    """launch's base of the handlers of one kind of event about an action (`action_matcher`:
    the action, a predicate of the action, or None for any)."""

    def __init__(self, *, action_matcher: Any, on_event: Any, target_event_cls: type,
                 target_action_cls: type, **kwargs: Any) -> None:
        def matcher(event: Any) -> bool:
            if not isinstance(event, target_event_cls):
                return False
            if action_matcher is None:
                return True
            if isinstance(action_matcher, LaunchDescriptionEntity) or \
                    not callable(action_matcher):
                return getattr(event, "action", None) is action_matcher
            return bool(action_matcher(getattr(event, "action", None)))

        super().__init__(matcher=matcher, **kwargs)
        self.target_action = action_matcher
        self.on_event = on_event
        self.event_name = target_event_cls.__name__

    @property
    def matcher_description(self) -> str:
        which = self.target_action
        if which is None:
            return f"event issubclass of {self.event_name}"
        target = f"{type(which).__name__}({hex(id(which))})" if isinstance(
            which, LaunchDescriptionEntity) else str(which)
        return f"event issubclass of {self.event_name} and event.action == {target}"

    @property
    def handler_description(self) -> str:
        return f"{self.on_event}"

    def describe(self) -> tuple[str, list[Any]]:
        return (f"{type(self).__name__}(matcher='{self.matcher_description}', "
                f"handler='{self.handler_description}')", _listed(self.on_event))

    def reaction(self, event: Any, context: LaunchContext) -> Any:
        return _answer(self.on_event, event, context)


class OnProcessStart(OnActionEventBase):
    """launch.event_handlers.OnProcessStart: `on_start` (entities, or a function of the event
    and the context) when a process starts."""

    def __init__(self, *, target_action: Any = None, on_start: Any, **kwargs: Any) -> None:
        super().__init__(action_matcher=target_action, on_event=on_start,
                         target_event_cls=events.ProcessStarted,
                         target_action_cls=Action, **kwargs)


class OnProcessExit(OnActionEventBase):
    """launch.event_handlers.OnProcessExit: `on_exit` when a process exits."""

    def __init__(self, *, target_action: Any = None, on_exit: Any, **kwargs: Any) -> None:
        super().__init__(action_matcher=target_action, on_event=on_exit,
                         target_event_cls=events.ProcessExited,
                         target_action_cls=Action, **kwargs)


class OnProcessIO(OnActionEventBase):
    """launch.event_handlers.OnProcessIO: a function of the event for each piece of a
    process's output (`on_stdout`, `on_stderr`)."""

    def __init__(self, *, target_action: Any = None, on_stdin: Any = None,
                 on_stdout: Any = None, on_stderr: Any = None, **kwargs: Any) -> None:
        self.on_stdin, self.on_stdout, self.on_stderr = on_stdin, on_stdout, on_stderr
        super().__init__(action_matcher=target_action, on_event=None,
                         target_event_cls=events.ProcessIO,
                         target_action_cls=Action, **kwargs)

    @property
    def handler_description(self) -> str:
        given = {name: getattr(self, name) for name in ("on_stdin", "on_stdout", "on_stderr")}
        return "{" + ", ".join(f"{name}: '{handler}'" for name, handler in given.items()
                               if handler is not None) + "}"

    def describe(self) -> tuple[str, list[Any]]:
        return (f"OnProcessIO(matcher='{self.matcher_description}', "
                f"handlers={self.handler_description})", [])

    def reaction(self, event: Any, context: LaunchContext) -> Any:
        answer = {0: self.on_stdin, 1: self.on_stdout, 2: self.on_stderr}.get(event.fd)
        return None if answer is None else answer(event)


class OnExecutionComplete(OnActionEventBase):
    """launch.event_handlers.OnExecutionComplete: `on_completion` when an action is done."""

    def __init__(self, *, target_action: Any = None, on_completion: Any,
                 **kwargs: Any) -> None:
        super().__init__(action_matcher=target_action, on_event=on_completion,
                         target_event_cls=events.ExecutionComplete,
                         target_action_cls=Action, **kwargs)


class OnShutdown(BaseEventHandler):
    """launch.event_handlers.OnShutdown: `on_shutdown` when the launch begins to end."""

    def __init__(self, *, on_shutdown: Any, **kwargs: Any) -> None:
        super().__init__(matcher=lambda event: isinstance(event, events.Shutdown), **kwargs)
        self.on_shutdown = on_shutdown

    def describe(self) -> tuple[str, list[Any]]:
        return ("OnShutdown(matcher='event issubclass of launch.events.Shutdown', "
                f"handler={self.on_shutdown})", _listed(self.on_shutdown))

    def reaction(self, event: Any, context: LaunchContext) -> Any:
        return _answer(self.on_shutdown, event, context)


class OnIncludeLaunchDescription(EventHandler):
    """launch.event_handlers.OnIncludeLaunchDescription: the launch's own handler of the
    IncludeLaunchDescription event (its description joins the launch)."""

    def __init__(self, **kwargs: Any) -> None:
        super().__init__(matcher=lambda e: isinstance(e, events.IncludeLaunchDescription),
                         **kwargs)

    def reaction(self, event: Any, context: LaunchContext) -> Any:
        return event.launch_description


def gen_handler(entities: Any) -> Callable[[Any, Any], Any]:
    """A handler function that answers any event with `entities`."""
    return lambda _event, _context: entities


def event_named(name: str) -> Callable[[Any], bool]:
    """launch.event_handlers.event_named: a matcher of the events of that type name."""
    return lambda event: getattr(event, "name", None) == name


def _is_function(reaction: Any) -> bool:
    """Whether a handler's reaction is a function of the event and the context (an action
    is callable too, and is an entity)."""
    return callable(reaction) and not isinstance(reaction, Action)


def _answer(reaction: Any, event: Any, context: LaunchContext) -> Any:
    return reaction(event, context) if _is_function(reaction) else reaction


def _listed(reaction: Any) -> list[Action]:
    """The entities a handler's describe() lists: none for a function."""
    return [] if _is_function(reaction) else _entities(reaction)


def _entities(value: Any) -> list[Action]:
    if value is None:
        return []
    if isinstance(value, LaunchDescriptionEntity):
        return [value]  # type: ignore[list-item]
    return [entity for entity in value if entity is not None]


@dataclass(kw_only=True, eq=False)
class HandlerAction(Action):
    """An action about an event handler (registering it, or taking it off)."""

    event_handler: Any

    def __init__(self, event_handler: Any, **kwargs: Any) -> None:
        self.event_handler = event_handler
        self.condition = kwargs.get("condition")
        self.where = kwargs.get("where")


class RegisterEventHandler(HandlerAction):
    """launch.actions.RegisterEventHandler."""

    def execute(self, context: LaunchContext) -> None:
        if context.service is None:
            return
        self.event_handler.snapshot = context.snapshot()
        context.service.register_handler(self.event_handler)


class UnregisterEventHandler(HandlerAction):
    """launch.actions.UnregisterEventHandler."""

    def execute(self, context: LaunchContext) -> None:
        context.unregister_event_handler(self.event_handler)
