"""launch.utilities: the helpers that launch's own actions use and users' actions call."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from launcher.description.action import LaunchDescriptionEntity
from launcher.description.substitution import Substitution, Text, perform_text, to_text


def is_a(obj: Any, entity_type: Any) -> bool:
    """Whether `obj` is an instance of `entity_type` (a class or a tuple of them)."""
    return isinstance(obj, entity_type)


def is_a_subclass(obj: Any, entity_type: Any) -> bool:
    """Whether `obj` is an instance or a subclass of `entity_type`."""
    return isinstance(obj, entity_type) or isinstance(obj, type) and \
        issubclass(obj, entity_type)


def isclassinstance(obj: Any) -> bool:
    """Whether `obj` is an instance of a class (not a class itself)."""
    return not isinstance(obj, type) and hasattr(obj, "__class__")


def ensure_argument_type(argument: Any, types: Any, argument_name: str,
                         caller: str | None = None) -> None:
    """Raise TypeError unless `argument` is of one of `types` (launch's check and message)."""
    kinds = list(types) if isinstance(types, Iterable) else [types]
    if any(isinstance(argument, kind) for kind in kinds if isinstance(kind, type)):
        return
    who = "E" if caller is None else f"'{caller}' e"
    raise TypeError(f"{who}xpected '{argument_name}' to be one of "
                    f"[{', '.join(str(kind) for kind in kinds)}], but got '{argument}' of type "
                    f"'{type(argument)}'")


def normalize_to_list_of_substitutions(subs: Any) -> list[Substitution]:
    """Text, a substitution, or a list of them, as a list of substitutions (text as
    launch.substitutions.TextSubstitution, as launch gives it)."""
    from launcher.api.substitutions import TextSubstitution

    return [TextSubstitution(text=item.text) if type(item) is Text else item
            for item in to_text(subs)]


def perform_substitutions(context: Any, subs: Any) -> str:
    return perform_text(context, tuple(normalize_to_list_of_substitutions(subs)))


def normalize_to_list_of_entities(entities: Iterable[Any]) -> list[Any]:
    """Entities and lists of them, flattened into one list."""
    flat: list[Any] = []
    for entity in entities:
        if isinstance(entity, LaunchDescriptionEntity):
            flat.append(entity)
        else:
            flat.extend(normalize_to_list_of_entities(entity))
    return flat


def visit_all_entities_and_collect_futures(entity: Any, context: Any) -> list[Any]:
    """Visit `entity` and what it gives, depth first: the (entity, future) pairs of those
    that have a future (launcher's actions have none: their completion is an event)."""
    found = []
    subs = entity.visit(context)
    future = entity.get_asyncio_future()
    if future is not None:
        found.append((entity, future))
    for sub in subs or ():
        found += visit_all_entities_and_collect_futures(sub, context)
    return found


class AsyncSafeSignalManager:
    """launch.utilities.AsyncSafeSignalManager: signal handlers that run on an asyncio loop
    (`with AsyncSafeSignalManager(loop) as manager: manager.handle(signal.SIGINT, f)`);
    they are taken off when the block ends."""

    def __init__(self, loop: Any) -> None:
        self.__loop = loop
        self.__handlers: dict[int, Any] = {}

    def __enter__(self) -> AsyncSafeSignalManager:
        return self

    def __exit__(self, *exc_info: Any) -> None:
        for signum in list(self.__handlers):
            self.__loop.remove_signal_handler(signum)
        self.__handlers.clear()

    def handle(self, signum: int, handler: Any) -> Any:
        """Run `handler(signum)` on the loop for `signum` (None: stop); the one before."""
        old = self.__handlers.pop(signum, None)
        if old is not None:
            self.__loop.remove_signal_handler(signum)
        if handler is not None:
            self.__handlers[signum] = handler
            self.__loop.add_signal_handler(signum, handler, signum)
        return old
