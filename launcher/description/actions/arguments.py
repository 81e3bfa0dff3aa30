"""Launch configurations: `arg` declares one, `let` sets one, `reset` clears them."""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from typing import Any

from launcher.description.action import Action
from launcher.description.actions.entries import NameValue
from launcher.description.fields import Kind, attr, resolve
from launcher.description.registry import action
from launcher.description.substitution import Text_, describe_text, perform_text
from launcher.errors import ExecutionError, did_you_mean
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext


@dataclass(eq=False)
class Choice:
    value: str = attr(Kind.NAME, required=True, doc="One valid value.")


@dataclass(eq=False)
class KeepEntry(NameValue):
    """A configuration to keep."""

    value: Text_ | None = attr(Kind.TEXT, doc="Its value (default: its current value).")


def kept_configurations(context: LaunchContext, entries: list[KeepEntry]) -> dict[str, str]:
    """The configurations that `keep` entries name: each given value, or the current one."""
    kept = {}
    for entry in entries:
        name = perform_text(context, entry.name)
        if entry.value is not None:
            kept[name] = perform_text(context, entry.value)
        elif name in context.configurations:
            kept[name] = context.configurations[name]
    return kept


@action("arg")
@dataclass(kw_only=True, eq=False)
class DeclareLaunchArgument(Action):
    name: str = attr(Kind.NAME, required=True, doc="The argument's name.")
    default_value: Any = attr(Kind.TEXT, name="default", doc="Used when not given.")
    given_description: str = attr(Kind.NAME, "", name="description",
                                  doc="Shown by --show-args and in errors.")
    choices: list[Any] = attr(Kind.ENTRIES, name="choice", entry=Choice,
                              doc="If given, the only valid values.")

    def __post_init__(self) -> None:
        super().__post_init__()
        self.choices = [c.value if isinstance(c, Choice) else str(c) for c in self.choices]

    @property
    def description(self) -> str:
        """As launch words it (what --show-args shows): the one given, with its choices."""
        return _described(self.given_description, self.choices)

    @property
    def required(self) -> bool:
        return self.default_value is None

    def describe_default(self) -> str:
        return "(required)" if self.default_value is None else \
            f"default: '{describe_text(self.default_value)}'"

    def execute(self, context: LaunchContext) -> None:
        context.declared.add(self.name)
        if self.name not in context.configurations:
            if self.default_value is None:
                raise missing_argument_error([self], context.configurations)
            context.configurations[self.name] = perform_text(context, self.default_value)
        value = context.configurations[self.name]
        if self.choices and value not in self.choices:
            raise ExecutionError(
                f"argument '{self.name}' is '{value}'; expected one of: "
                f"{', '.join(self.choices)}{did_you_mean(value, self.choices)}"
            )


def missing_argument_error(
    args: Iterable[DeclareLaunchArgument], given: dict[str, str]
) -> ExecutionError:
    args = list(args)
    lines = [f"  {a.name}: {a.description or '(no description)'}" for a in args]
    names = ", ".join(f"'{a.name}'" for a in args)
    hint = " ".join(f"{a.name}:=VALUE" for a in args)
    error = ExecutionError(
        f"required argument{'s' if len(args) > 1 else ''} {names} not given; "
        f"pass {hint}\n" + "\n".join(lines)
        + (f"\n  given: {', '.join(sorted(given))}" if given else "")
    )
    return error.at(args[0].where)


def declared_arguments(actions: Sequence[Action]) -> list[DeclareLaunchArgument]:
    """The `arg`s a description declares, looking into groups but not into includes."""
    found: list[DeclareLaunchArgument] = []
    for item in actions:
        if isinstance(item, DeclareLaunchArgument):
            found.append(item)
        elif not getattr(item, "is_include", False):
            found.extend(declared_arguments(item.sub_actions()))
    return found


def declared_args(actions: Sequence[Action]) -> set[str]:
    """The names a roslaunch file declares as `<arg>` (with default=, or value= as a constant
    `let`), looking into groups but not into includes: what an include may pass it."""
    names = {a.name for a in declared_arguments(actions)}

    def constants(items: Sequence[Action]) -> None:
        for item in items:
            if isinstance(item, SetLaunchConfiguration) and item.fixed not in (None, False):
                names.add(describe_text(item.name))
            elif not getattr(item, "is_include", False):
                constants(item.sub_actions())

    constants(actions)
    return names


def check_required(actions: Sequence[Action], given: dict[str, str]) -> None:
    """Fail before anything runs if a required argument (no default, no condition) is missing."""
    missing = [a for a in declared_arguments(actions)
               if a.required and a.condition is None and a.name not in given]
    if missing:
        raise missing_argument_error(missing, given)


@action("let")
@dataclass(kw_only=True, eq=False)
class SetLaunchConfiguration(Action):
    name: Text_ = attr(Kind.TEXT, required=True, doc="The configuration to set.")
    value: Text_ = attr(Kind.TEXT, required=True, doc="Its new value.")
    fixed: Any = attr(Kind.BOOL, False, doc="roslaunch's `<arg value=>`: a constant; a value "
                                            "given for it (command line, include) is an "
                                            "error, unless the file was included with "
                                            "pass_all_args.")

    def execute(self, context: LaunchContext) -> None:
        name = perform_text(context, self.name)
        fixed = self.fixed is not None and resolve(context, self.fixed, Kind.BOOL, "fixed")
        if fixed:
            context.declared.add(name)  # an arg of the file's, for the command line's check
        if fixed and name in context.configurations and \
                context.configurations.get(PASS_ALL_ARGS) != "true":
            raise ExecutionError(f"Invalid <arg> tag: cannot override arg '{name}', which has "
                                 "already been set (an <arg value=> is a constant: it takes "
                                 "no value from the command line or an include; use "
                                 "default= to let it)", self.where)
        context.configurations[name] = perform_text(context, self.value)


PASS_ALL_ARGS = "<pass_all_args>"  # whether roslaunch's include passed every arg


@action("reset")
@dataclass(kw_only=True, eq=False)
class ResetLaunchConfigurations(Action):
    keep: list[KeepEntry] = attr(Kind.ENTRIES, entry=KeepEntry,
                                 doc="Configurations that survive the reset.")

    def execute(self, context: LaunchContext) -> None:
        kept = kept_configurations(context, self.keep)
        context.configurations.clear()
        context.configurations.update(kept)


def _described(description: str, choices: list[str]) -> str:
    """The argument's description as launch words it (what --show-args shows)."""
    if not description:
        return f"One of: {choices}" if choices else "no description given"
    if choices and "Valid choices are: " not in description:
        return f"{description.rstrip('.')}. Valid choices are: {choices}"
    return description
