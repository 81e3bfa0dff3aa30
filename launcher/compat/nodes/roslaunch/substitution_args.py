"""roslaunch.substitution_args: `$(arg)`, `$(env)`, `$(optenv)`, `$(find)`, `$(anon)`,
`$(dirname)` and `$(eval)` resolved in a string, by launcher's roslaunch grammar
(frontend/roslaunch_substitutions.py) and its substitutions: the same rules as in a launch
file. `context` is roslaunch's dict: its 'arg' the arguments, its 'anon' the anonymous names
made so far (kept there, so that the same name resolves the same in every call)."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from launcher.errors import LaunchError


class SubstitutionException(Exception):
    """A substitution that cannot be resolved (a typo, a missing package)."""


class ArgException(SubstitutionException):
    """`$(arg NAME)` of an argument that has no value; the exception's text is the name."""


def resolve_args(arg_str: Any, context: dict[str, Any] | None = None, resolve_anon: bool = True,
                 filename: str | None = None) -> Any:
    """`arg_str` with its substitutions resolved (None and '' come back as they are);
    with `resolve_anon` False, `$(anon NAME)` is left as written."""
    if not arg_str:
        return arg_str
    from launcher.description.substitutions.configuration import AnonName, LaunchConfiguration
    from launcher.frontend.builder import parse_file_text

    context = {} if context is None else context
    launch = _launch_context(context, filename)
    try:
        parts = parse_file_text(arg_str, filename or "<string>", roslaunch=True)
    except LaunchError as exc:
        raise SubstitutionException(f"{exc.message} [{arg_str}]") from None
    out = []
    for part in parts:
        if isinstance(part, AnonName) and not resolve_anon:
            out.append(f"$(anon {_text(part.name, launch)})")
            continue
        if isinstance(part, LaunchConfiguration):
            name = _text(part.name, launch)
            if name not in launch.configurations:
                raise ArgException(name)
        out.append(_text((part,), launch))
    return "".join(out)


def _launch_context(context: dict[str, Any], filename: str | None) -> Any:
    from launcher.packages.index import PackageIndex
    from launcher.runtime.context import LaunchContext

    arguments = context.setdefault("arg", {})
    launch = LaunchContext(os.environ, {str(k): _word(v) for k, v in arguments.items()
                                        if v is not None},
                           packages=PackageIndex.from_environment(os.environ))
    launch.anonymous_names = context.setdefault("anon", {})  # (shared: the same on each call)
    name = filename or context.get("filename")
    if name:
        launch.files.push(Path(os.path.abspath(name)))
    return launch


def _text(text: Any, launch: Any) -> str:
    from launcher.description.substitution import perform_text

    try:
        return perform_text(launch, text)
    except LaunchError as exc:
        raise SubstitutionException(exc.message) from None


def _word(value: Any) -> str:
    return str(value).lower() if isinstance(value, bool) else str(value)


def convert_value(value: str, type_: str) -> Any:
    """roslaunch.loader.convert_value: `value` as `type_` says (str, int, double, bool, yaml,
    auto …)."""
    from launcher.compat.nodes.roslaunch.loader import convert_value as convert

    return convert(value, type_)
