"""Launch configurations and loop variables: `$(var)`, `$(index)`, `$(for-var)`, `$(anon)`."""

from __future__ import annotations

import os

from launcher.description.substitution import Substitution, Text_, perform_text, substitution
from launcher.errors import did_you_mean
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext


@substitution("var")
@dataclass(frozen=True)
class LaunchConfiguration(Substitution):
    """The value of a launch argument or `let` (roslaunch's `$(arg)` is read as it)."""

    name: Text_
    default: Text_ | None = None

    def perform(self, context: LaunchContext) -> str:
        name = perform_text(context, self.name)
        if name in context.configurations:
            return context.configurations[name]
        if self.default is not None:
            return perform_text(context, self.default)
        hint = did_you_mean(name, context.configurations)
        raise self.fail(
            f"launch configuration '{name}' is not set{hint}; declare it with an 'arg' or "
            f"'let', pass {name}:=VALUE, or give a default: $(var {name} DEFAULT)"
        )


def loop_key(name: str) -> str:
    return f"for:{name}"


@substitution("for-var")
@dataclass(frozen=True)
class ForEachVar(Substitution):
    """A value of the current `for_each` iteration."""

    name: Text_
    default: Text_ | None = None

    def perform(self, context: LaunchContext) -> str:
        name = perform_text(context, self.name)
        key = loop_key(name)
        if key in context.locals:
            return context.locals[key]
        if self.default is not None:
            return perform_text(context, self.default)
        known = [k[4:] for k in context.locals if k.startswith("for:")]
        raise self.fail(
            f"loop variable '{name}' is not set{did_you_mean(name, known)}; "
            "$(for-var) works inside a 'for_each' (or 'for') block"
        )


@substitution("index")
@dataclass(frozen=True)
class ForLoopIndex(Substitution):
    """The index of the enclosing `for` loop of that name."""

    name: Text_

    def perform(self, context: LaunchContext) -> str:
        name = perform_text(context, self.name)
        key = loop_key(name)
        if key not in context.locals:
            raise self.fail(f"no 'for' loop named '{name}' encloses this $(index)")
        return context.locals[key]


@substitution("anon")
@dataclass(frozen=True)
class AnonName(Substitution):
    """A name unique to this run and stable for the same NAME within it, made as roslaunch
    and launch make it: NAME_<host>_<pid>_<random>, '.', '-' and ':' made '_'."""

    name: Text_

    def perform(self, context: LaunchContext) -> str:
        name = perform_text(context, self.name)
        if name not in context.anonymous_names:
            import random
            import socket
            import sys

            made = f"{name}_{socket.gethostname()}_{os.getpid()}_{random.randint(0, sys.maxsize)}"
            context.anonymous_names[name] = made.replace(".", "_").replace("-", "_") \
                .replace(":", "_")
        return context.anonymous_names[name]
