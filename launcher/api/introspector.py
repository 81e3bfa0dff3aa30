"""launch.LaunchIntrospector: a launch description as the tree of text launch prints."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from launcher.description.action import Action
from launcher.description.actions.event_handlers import RegisterEventHandler
from launcher.description.actions.executable import ExecuteProcess
from launcher.description.actions.log import LogInfo
from launcher.description.substitution import Text, to_text


def indent(lines: list[str], indention: str = "    ") -> list[str]:
    return [f"{indention}{line}" for line in lines]


def tree_like_indent(lines: list[str]) -> list[str]:
    """Lines indented by four spaces a level, drawn as a tree (├──, └──, │)."""
    result: list[str] = []
    before: int | None = None
    for old in lines:
        if not old.startswith("    "):
            continue
        depth = len(old) - len(old.lstrip())
        if before is not None and "└" in result[-1] and before <= depth:
            result[-1] = result[-1].replace("└", "├", 1)
        before = depth
        line = "│" + old[1:]
        result.append(line[:depth - 4] + "└── " + line[depth:])
    if result and result[-1].startswith("│"):
        result[-1] = " " + result[-1][1:]
    return result


def format_substitutions(substitutions: Any) -> str:
    return " + ".join(_describe(part) for part in to_text(substitutions))


def _describe(part: Any) -> str:
    return f"'{part.text}'" if type(part) is Text or type(part).__name__ == \
        "TextSubstitution" else part.describe()


def format_event_handler(event_handler: Any) -> list[str]:
    if not hasattr(event_handler, "describe"):
        return [f"EventHandler('{hex(id(event_handler))}')"]
    description, entities = event_handler.describe()
    entities = [entities] if isinstance(entities, Action) else list(entities or ())
    return [description, *indent(format_entities(entities))]


def format_action(action: Any) -> list[str]:
    if isinstance(action, LogInfo):
        return [f"LogInfo({format_substitutions(action.msg)})"]
    if type(action).__name__ == "EmitEvent":
        return [f"EmitEvent(event='{action.event.name}')"]
    if isinstance(action, ExecuteProcess):
        cmd = ", ".join(format_substitutions(part) for part in action.cmd)
        cwd = None if action.cwd is None else f"'{format_substitutions(action.cwd)}'"
        env = None if action.env is None else "{" + ", ".join(
            f"{format_substitutions(key)}: {format_substitutions(value)}"
            for key, value in dict(action.env).items()) + "}"
        return [f"ExecuteProcess(cmd=[{cmd}], cwd={cwd}, env={env}, "
                f"shell={bool(getattr(action, 'shell', False))})"]
    if isinstance(action, RegisterEventHandler):
        return [f"RegisterEventHandler('{action.event_handler}'):",
                *indent(format_event_handler(action.event_handler))]
    # (launch's actions print as objects; launcher's own would print their fields)
    shown = object.__repr__(action) if type(action).__module__.startswith("launcher.") \
        else str(action)
    return [f"Action('{shown}')"]


def format_entities(entities: Iterable[Any]) -> list[str]:
    result: list[str] = []
    for entity in entities:
        result.extend(format_action(entity) if isinstance(entity, Action)
                      else [f"Unknown entity('{entity}')"])
    return result


class LaunchIntrospector:
    """Visits a launch description's entities, to show them."""

    def format_launch_description(self, launch_description: Any) -> str:
        lines = tree_like_indent(indent(format_entities(launch_description.entities)))
        return f"{launch_description}\n" + "\n".join(lines)
