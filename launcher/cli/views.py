"""Static views of a launch description: `--show-args` and `--print`.

Nothing is run. Included files are read when their path can be worked out from the arguments
and defaults known so far; otherwise the include is shown unresolved.
"""

from __future__ import annotations

import contextlib
from collections.abc import Iterator
from typing import Any

from launcher import records
from launcher.description.action import Action, LaunchDescription, PopLocals, PushLocals
from launcher.description.actions.arguments import DeclareLaunchArgument
from launcher.description.actions.include import IncludeLaunchDescription
from launcher.description.actions.loops import ForEach, ForLoop
from launcher.description.fields import declared_fields, frontend_name
from launcher.description.parameters import Written
from launcher.description.substitution import Substitution, describe_text, perform_text
from launcher.errors import LaunchError
from launcher.frontend.builder import parse_file_text
from launcher.frontend.loader import load_file
from launcher.runtime.context import LaunchContext


def _context(configurations: dict[str, str], index: Any) -> LaunchContext:
    context = LaunchContext(configurations=configurations, load_description=load_file,
                            parse_text=parse_file_text,
                            packages=index)
    return context


def _walk(actions: list[Action], context: LaunchContext, depth: int, loops: bool = False
          ) -> Iterator[tuple[int, Action, LaunchDescription | str | None]]:
    """Yield (depth, action, included description or why it is unresolved). With `loops`, a
    `for`/`for_each` body is walked as its first pass (its `$(index)` and `$(for-var)` set),
    so that what it includes can be read."""
    for item in actions:
        if isinstance(item, PushLocals | PopLocals):  # a loop's pass begins or ends
            item.execute(context)
        elif loops and isinstance(item, ForLoop | ForEach):
            yield depth, item, None
            try:
                passes = list(item.execute(context))
            except LaunchError:
                passes = []
            ends = [i for i, a in enumerate(passes) if isinstance(a, PopLocals)]
            first = passes[:ends[0] + 1] if ends else list(item.sub_actions())
            yield from _walk(first, context, depth + 1, loops)
        elif isinstance(item, DeclareLaunchArgument):
            if item.name not in context.configurations and item.default_value is not None:
                with contextlib.suppress(LaunchError):
                    context.configurations[item.name] = perform_text(context,
                                                                     item.default_value)
            yield depth, item, None
        elif isinstance(item, IncludeLaunchDescription):
            try:
                included = item.load(context)
                for arg in item.launch_arguments:
                    context.configurations[perform_text(context, arg.name)] = \
                        perform_text(context, arg.value)
            except LaunchError as exc:
                yield depth, item, f"not resolved statically: {exc.message}"
                continue
            yield depth, item, included
            context.files.push(included.file)
            yield from _walk(included.actions, context, depth + 1, loops)
            context.files.pop()
        else:
            yield depth, item, None
            yield from _walk(list(item.sub_actions()), context, depth + 1, loops)


def argument_sections(description: LaunchDescription, configurations: dict[str, str],
                      index: Any = None) -> tuple[dict[str, list[DeclareLaunchArgument]],
                                                  list[str]]:
    """The launch arguments the file and each file it includes declare (by file, as
    `--show-args` lists them), and why an include's could not be listed."""
    context = _context(dict(configurations), index)
    context.files.push(description.file)
    sections: dict[str, list[DeclareLaunchArgument]] = {str(description.file): []}
    current = [str(description.file)]
    notes: list[str] = []
    depth_files: dict[int, str] = {0: str(description.file)}
    for depth, item, extra in _walk(description.actions, context, 0, loops=True):
        if isinstance(item, DeclareLaunchArgument):
            section = sections.setdefault(depth_files.get(depth, current[-1]), [])
            if all(arg.name != item.name for arg in section):
                section.append(item)
        elif isinstance(item, IncludeLaunchDescription):
            if isinstance(extra, LaunchDescription):
                depth_files[depth + 1] = str(extra.file)
                sections.setdefault(str(extra.file), [])
            elif extra:
                notes.append(f"include at {item.where}: {extra}")
    return sections, notes


def argument_names(description: LaunchDescription, configurations: dict[str, str],
                   index: Any = None) -> tuple[list[str], list[str]]:
    """Every launch argument's name (`launcher batch` checks its matrix against them), and
    why an include's could not be listed."""
    sections, notes = argument_sections(description, configurations, index)
    names = [arg.name for args in sections.values() for arg in args]
    return list(dict.fromkeys(names)), notes


def show_arguments(description: LaunchDescription, configurations: dict[str, str],
                   index: Any = None) -> str:
    sections, notes = argument_sections(description, configurations, index)
    lines = ["Arguments (pass arguments as '<name>:=<value>'):"]
    for file, args in sections.items():
        title = "" if file == str(description.file) else f"\n  from included {file}:"
        if title:
            lines.append(title)
        if not args:
            lines.append("\n    (none)" if not title else "    (none)")
        for arg in args:
            lines.append(f"\n    '{arg.name}':")
            lines.append(f"        {arg.description}")
            lines.append(f"        ({arg.describe_default()})")
    if notes:
        lines += ["", "Includes whose arguments could not be listed:",
                  *(f"  {note}" for note in notes)]
    return "\n".join(lines) + "\n"


def print_tree(description: LaunchDescription, configurations: dict[str, str],
               index: Any = None) -> str:
    context = _context(dict(configurations), index)
    context.files.push(description.file)
    lines = [f"LaunchDescription {description.file}"]
    for depth, item, extra in _walk(description.actions, context, 0):
        text = "  " * (depth + 1) + _describe(item)
        if isinstance(item, DeclareLaunchArgument) and item.name in context.configurations:
            source = "the command line" if item.name in configurations else "its default"
            text += f"  -> {context.configurations[item.name]!r} ({source})"
        if isinstance(extra, LaunchDescription):
            text += f"  -> {extra.file}"
        elif isinstance(extra, str):
            text += f"  ({extra})"
        lines.append(text)
    return "\n".join(lines) + "\n"


def _describe(item: Action) -> str:
    tag = item.tags[0] if item.tags else type(item).__name__
    parts = [tag]
    if records.is_record(item):
        for field, spec in declared_fields(type(item)):
            value = getattr(item, field.name, None)
            if value in (None, [], (), field.default) or spec.kind.value == "children":
                continue
            parts.append(f"{frontend_name(field, spec)}={_show(value)}")
    if item.condition is not None:
        parts.append(item.condition.describe())
    return " ".join(parts)


def _show(value: Any) -> str:
    if isinstance(value, tuple) and all(isinstance(v, Substitution) for v in value):
        return repr(describe_text(value))
    if isinstance(value, Written):  # a parameter value: a string shows its quotes
        text = value.describe()  # (and one with a line break shows it escaped: one line each)
        return repr(text) if value.string or "\n" in text else text
    if isinstance(value, list):
        return "[" + ", ".join(_show_entry(v) for v in value) + "]"
    return repr(value)


def _show_entry(value: Any) -> str:
    if isinstance(value, Action):
        return _describe(value)
    if records.is_record(value) and not isinstance(value, Written):
        shown = [(f.name, getattr(value, f.name)) for f in records.fields(value)
                 if f.name != "where"]
        return "{" + ", ".join(f"{name}: {_show(item)}" for name, item in shown
                               if item not in (None, [], False)) + "}"
    return _show(value)


