"""Launch configurations and loop variables: `$(var)`, `$(index)`, `$(for-var)`, `$(anon)`."""

from __future__ import annotations

import os
from collections.abc import Mapping

from launcher.description.substitution import Substitution, Text_, perform_text, substitution
from launcher.description.substitutions.lookup import Lookup
from launcher.errors import did_you_mean
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext


@substitution("var")
@dataclass(frozen=True)
class LaunchConfiguration(Lookup):
    """The value of a launch argument or `let` (roslaunch's `$(arg)` is read as it)."""

    def _values(self, context: LaunchContext) -> Mapping[str, str]:
        return context.configurations

    def _unset(self, name: str, values: Mapping[str, str]) -> str:
        return (f"launch configuration '{name}' is not set{did_you_mean(name, values)}; "
                f"declare it with an 'arg' or 'let', pass {name}:=VALUE, or give a default: "
                f"$(var {name} DEFAULT)")


_LOOP = "for:"  # (a loop variable's key among the context's locals)


def loop_key(name: str) -> str:
    return _LOOP + name


@substitution("for-var")
@dataclass(frozen=True)
class ForEachVar(Lookup):
    """A value of the current `for_each` iteration."""

    def _values(self, context: LaunchContext) -> Mapping[str, str]:
        return {key[len(_LOOP):]: value for key, value in context.locals.items()
                if key.startswith(_LOOP)}

    def _unset(self, name: str, values: Mapping[str, str]) -> str:
        return (f"loop variable '{name}' is not set{did_you_mean(name, values)}; "
                "$(for-var) works inside a 'for_each' (or 'for') block")


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
