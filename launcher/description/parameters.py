"""ROS parameters for nodes: typing values, the run-wide settings, and params files.

Run-wide settings (`push_ros_namespace`, `set_parameter`, `set_parameters_from_file`,
`set_remap`) live in the launch configurations under reserved keys, so `group` scopes them as
it scopes arguments (as in ROS 2). Values are typed like ROS 2 types them, with one rule
ROS 2 lacks: text that spans lines (a robot description, any XML) is always a string and is
never parsed as YAML.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

from launcher.description.substitution import (
    Text,
    Text_,
    describe_text,
    is_literal,
    perform_text,
    to_text,
)
from launcher.errors import ExecutionError, Location, did_you_mean
from launcher.private import private_folder, write_private
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext
from launcher.user_files import read_text

NAMESPACE = "<ros_namespace>"
GLOBAL_PARAMETERS = "<global_parameters>"  # a tuple of (name, value) and (FILE, path) items
PRIVATE_PARAMETERS = "<private_parameters>"  # roslaunch's ~name outside a node: (name, value)
FILE = "<file>"
REMAPS = "<remaps>"  # a tuple of (from, to)
LIST_TYPES = {"list_of_str": "str", "list_of_int": "int", "list_of_float": "float",
              "list_of_bool": "bool"}
# roslaunch's type= (its loader.convert_value), as `ros1:<type>`; ros1:auto for none given
ROS1_TYPES = ("str", "string", "int", "double", "bool", "boolean", "yaml", "auto")
TYPES = ("str", "int", "float", "bool", "yaml", *LIST_TYPES, *(f"ros1:{t}" for t in ROS1_TYPES))
_TRUE = ("true", "yes", "on", "1")
_FALSE = ("false", "no", "off", "0")


@dataclass(frozen=True)
class Written:
    """A parameter value as the file wrote it: its text (with substitutions), and whether the
    file's own syntax already made it a string (a quoted YAML scalar, a Python str)."""

    text: Text_
    string: bool = False

    def describe(self) -> str:
        return describe_text(self.text)


def value_of(context: LaunchContext, value: Written | list[Written], kind: str | None,
             name: str, separator: str | None = None) -> Any:
    """The parameter value as launch_ros types it.

    Without a type: text the file made a string stays one (`'42'`, `'True'`, `'[1, 2]'`);
    a YAML number, bool or list is one; XML text and substitution results follow YAML's
    rules. Text of several lines (a robot description) is always a string. With `type:`,
    the written text is converted to it (launch_ros refuses `value: 42` with `type: str`;
    launcher gives "42"). `separator` (XML's `value-sep`) splits the text into a list.
    """
    if kind is not None and kind.startswith("ros1:") and isinstance(value, Written):
        return roslaunch_value(perform_text(context, value.text), kind[len("ros1:"):], name)
    if isinstance(value, Written) and separator:
        text = perform_text(context, value.text)
        value = [Written((Text(part),)) for part in text.split(separator)]
    item_kind = LIST_TYPES.get(kind or "")
    if isinstance(value, list):
        if kind is not None and kind != "yaml" and item_kind is None:
            raise ExecutionError(f"param '{name}': type {kind} takes one value, got a list")
        items = [_scalar(context, w, item_kind, name) for w in value]
        return _uniform(items, name)
    if item_kind is not None:
        listed = _yaml_value(perform_text(context, value.text), name)
        if not isinstance(listed, list):
            raise ExecutionError(f"param '{name}': type {kind} expects a list such as "
                                 f"[a, b], got '{perform_text(context, value.text)}'")
        return _uniform([_convert(_literal(v), item_kind, name) for v in listed], name)
    return _scalar(context, value, kind, name)


def _scalar(context: LaunchContext, written: Written, kind: str | None, name: str) -> Any:
    text = perform_text(context, written.text)
    if kind not in (None, "yaml"):
        return _convert(text, kind, name)
    if written.string and is_literal(written.text):
        return text
    return _yaml_value(text, name)


def _yaml_value(text: str, name: str) -> Any:
    """Text by YAML's rules, as launch_ros reads XML text and substitution results."""
    import yaml  # only where a value is read or written: a launch's start needs none

    if "\n" in text.strip() or not text.strip():
        return text  # robot descriptions and other documents stay text; so does ''
    try:
        value = yaml.safe_load(text)
    except yaml.YAMLError:
        return text
    if isinstance(value, bool | int | float | str):
        return value
    if isinstance(value, list):
        if any(not isinstance(v, bool | int | float | str) for v in value):
            raise ExecutionError(f"param '{name}': '{text}' is a list holding lists or maps; "
                                 "a parameter list holds numbers, bools or strings")
        return _uniform(value, name)
    if isinstance(value, dict):
        raise ExecutionError(f"param '{name}': '{text}' is a YAML map; a parameter holds one "
                             "value or a list (nest 'param' entries for a map, or give "
                             "type: str to keep the text)")
    return text  # null, dates: the text as written


def _literal(value: Any) -> str:
    return str(value).lower() if isinstance(value, bool) else str(value)


def _convert(text: str, kind: str, name: str, written: str = "") -> Any:
    """`text` as `type:` says (`written`: the type as the file spells it, for the error)."""
    if kind == "str":
        return text
    if kind in ("int", "float"):
        try:
            return int(text.strip()) if kind == "int" else float(text)
        except ValueError:
            said = written or kind
            raise ExecutionError(f"param '{name}': '{text}' is not {'an' if kind == 'int' else 'a'}"
                                 f" {said}") from None
    if kind == "bool":
        low = text.strip().lower()
        if low not in _TRUE + _FALSE:
            raise ExecutionError(f"param '{name}': '{text}' is not a bool; expected true or "
                                 "false (or 1 or 0)")
        return low in _TRUE
    raise ExecutionError(f"param '{name}': unknown type '{kind}'; expected one of "
                         f"{', '.join(TYPES)}{did_you_mean(kind, TYPES)}")


def roslaunch_value(text: str, kind: str, name: str) -> Any:
    """`text` as roslaunch's loader.convert_value types it: `auto` (no type=) is a float
    with a dot, an int (Python's int(), but 1_000 stays text), true/false, else the text;
    `bool` takes true/false/1/0 alone; `yaml` may be a map (a namespace of parameters)."""
    if kind == "auto":
        try:
            if "." in text:
                return float(text)
            if "_" not in text:
                return int(text)
        except ValueError:
            pass
        return text.lower() == "true" if text.lower() in ("true", "false") else text
    if kind in ("str", "string", "int", "double"):
        return _convert(text, {"string": "str", "double": "float"}.get(kind, kind), name, kind)
    if kind in ("bool", "boolean"):
        low = text.lower().strip()
        if low not in ("true", "1", "false", "0"):
            raise ExecutionError(f"param '{name}': '{text}' is not a bool; roslaunch's bool is "
                                 "true, false, 1 or 0")
        return low in ("true", "1")
    if kind == "yaml":
        import yaml  # only where a value is read or written: a launch's start needs none

        try:
            return yaml.load(text, Loader=ros1_yaml_loader())  # noqa: S506 - a SafeLoader
        except yaml.YAMLError as exc:
            raise ExecutionError(f"param '{name}': not valid YAML: {exc}") from None
    raise ExecutionError(f"param '{name}': unknown type '{kind}'; roslaunch's types are "
                         f"{', '.join(ROS1_TYPES)}{did_you_mean(kind, ROS1_TYPES)}")


_ros1_loader: Any = None


def ros1_yaml_loader() -> Any:
    """YAML as roslaunch reads its parameters (rosparam's loader): a safe loader that also
    reads angles, `rad(pi/2)` (an expression of pi, never Python's eval) and `deg(180)`, as
    radians, and the tags `!radians` and `!degrees`."""
    global _ros1_loader
    if _ros1_loader is None:
        import math
        import re

        import yaml

        class Ros1Loader(yaml.SafeLoader):
            pass

        def angle(kind: str) -> Any:
            def construct(loader: Any, node: Any) -> float:
                text = str(loader.construct_scalar(node)).strip()
                inner = text[4:-1] if text.startswith(f"{kind[:3]}(") else text
                try:
                    if kind == "degrees":
                        return float(inner) * math.pi / 180.0
                    from launcher.description.safe_expression import evaluate

                    return float(evaluate(inner, {"pi": math.pi}))  # type: ignore[arg-type]
                except Exception:  # noqa: BLE001 - said as rosparam says it
                    raise yaml.constructor.ConstructorError(
                        None, None, f"invalid {kind[:-1]} expression: {text}",
                        node.start_mark) from None
            return construct

        for kind in ("radians", "degrees"):
            Ros1Loader.add_constructor(f"!{kind}", angle(kind))
            Ros1Loader.add_implicit_resolver(f"!{kind}", re.compile(rf"^{kind[:3]}\([^)]*\)$"),
                                             [kind[0]])
        _ros1_loader = Ros1Loader
    return _ros1_loader


def unrolled(name: str, value: Any) -> dict[str, Any]:
    """A parameter whose value is a map (roslaunch's type="yaml"), as the parameters below
    `name` (dotted), as roslaunch's loader unrolls it; any other value as itself."""
    if not isinstance(value, dict):
        return {name: value}
    out: dict[str, Any] = {}
    for key, inner in value.items():
        out.update(unrolled(f"{name}.{key}" if name else str(key), inner))
    return out


def _uniform(items: list[Any], name: str) -> list[Any]:
    """A ROS list parameter holds one type; ints among floats become floats, as in launch_ros."""
    kinds = {type(v) for v in items}
    if kinds == {int, float}:
        return [float(v) for v in items]
    if len(kinds) > 1:
        found = ", ".join(sorted(k.__name__ for k in kinds))
        raise ExecutionError(f"param '{name}': the list mixes {found}; a ROS list parameter "
                             "holds one type (quote the items to make them all strings)")
    return items


def ros1_value(command: Text_ | None, textfile: Text_ | None) -> Written | None:
    """roslaunch's `<param command=…>` (the command's output) or `textfile=` (the file's
    text), as a value."""
    from launcher.description.substitutions.command import Command
    from launcher.description.substitutions.files import FileContent

    if command is not None:
        return Written((Command(command, (Text("warn"),)),), string=True)
    if textfile is not None:
        return Written((FileContent(textfile),), string=True)
    return None


def rosparam_values(context: LaunchContext, text: str, prefix: str, where: Any,
                    substitute: bool = False) -> dict[str, Any]:
    """roslaunch's `<rosparam>` YAML (a plain map, nested maps for namespaces) as dotted
    parameter names under `prefix`; `substitute`: its substitutions performed first."""
    import yaml  # only where a value is read or written: a launch's start needs none

    if substitute:
        if context.parse_text is None:
            raise ExecutionError("this run cannot read substitutions in files", where)
        text = perform_text(context, context.parse_text(text, str(getattr(where, "file", "")),
                                                        roslaunch=True))
    try:
        document = yaml.load(text, Loader=ros1_yaml_loader())  # noqa: S506 - a SafeLoader
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark
        raise ExecutionError(f"rosparam: not valid YAML: {exc.problem}"
                             + (f" (line {mark.line + 1} of the YAML)" if mark else ""),
                             where) from None
    if document is None:
        return {}
    if not isinstance(document, dict):
        if not prefix:
            raise ExecutionError("rosparam: expected a map of parameters (or give param= to "
                                 "name the value)", where)
        return {prefix: document}
    return unrolled(prefix.replace("/", "."), document)


def python_value(value: Any) -> Written:
    """A value the Python API gave: a str is a string, a substitution typed by YAML's rules."""
    if isinstance(value, str):
        return Written((Text(value),), string=True)
    if isinstance(value, bool | int | float):
        return Written((Text(_literal(value)),))
    return Written(to_text(value))


def parameter_argument(name: str, value: Any) -> str:
    """`name:=value` for `--ros-args -p`, as launch_ros writes a `set_parameter`: a string as
    it is (the node reads `true` or `5` in it by YAML's rules, as in ROS 2), anything else in
    YAML's flow style."""
    import yaml  # only where a value is read or written: a launch's start needs none

    if isinstance(value, str):
        return f"{name}:={value}"
    text = yaml.safe_dump(value, default_flow_style=True, width=float("inf")).strip()
    if text.endswith("\n..."):
        text = text[: -len("\n...")].strip()
    elif text.endswith("..."):
        text = text[:-3].strip()
    return f"{name}:={text}"


def _add(context: LaunchContext, key: str, items: tuple) -> None:
    context.configurations[key] = (*context.configurations.get(key, ()), *items)  # type: ignore


def global_settings(context: LaunchContext) -> tuple[tuple[str, Any], ...]:
    """`set_parameter` values as (name, value) and `set_parameters_from_file` files as
    (FILE, path), in the order given: later ones win, as on a node's command line."""
    return context.configurations.get(GLOBAL_PARAMETERS, ())  # type: ignore[return-value]


def global_parameters(context: LaunchContext) -> dict[str, Any]:
    return {name: value for name, value in global_settings(context) if name != FILE}


def add_global_parameter(context: LaunchContext, name: str, value: Any) -> None:
    _add(context, GLOBAL_PARAMETERS, ((name, value),))


def add_private_parameter(context: LaunchContext, name: str, value: Any) -> None:
    """roslaunch's `<param name="~x">` outside a node: a parameter of each node after it in its
    scope, as if the node had declared it (on the server under the node's name)."""
    _add(context, PRIVATE_PARAMETERS, ((name, value),))


def private_parameters(context: LaunchContext) -> dict[str, Any]:
    return dict(context.configurations.get(PRIVATE_PARAMETERS, ()))  # type: ignore[arg-type]


def add_graph_parameter(context: LaunchContext, name: str, value: Any,
                        load: Callable[[Path], Any], folder: Path) -> None:
    """A ROS 1 parameter (its full name) for the graph's parameter server (see _queue_load
    for `load` and `folder`)."""
    context.graph_parameters[name] = value
    _queue_load(context, load, folder)


def graph_command(context: LaunchContext, command: list[str], load: Callable[[Path], Any],
                  folder: Path) -> None:
    """`<rosparam command="delete">` (and clear_params): `["delete", name]`, the name and
    everything below it; `<rosparam command="dump">`: `["dump", name, file]`. Both act on
    what the server holds before it takes the launch's values, in the order given, as
    roslaunch runs `rosparam delete|dump` before it uploads the launch's parameters (so what
    the launch sets stays, and is not dumped)."""
    context.graph_commands.append(command)
    _queue_load(context, load, folder)


def _queue_load(context: LaunchContext, load: Callable[[Path], Any], folder: Path) -> None:
    """The first change chooses the file they will be written to, in `folder`, and queues
    `load(file)`, the action that puts them on the server, after everything queued now (the
    rest of the launch files: roslaunch sets the whole tree's parameters at once). Until they
    are set, the nodes wait (Runtime.hold_graph)."""
    if context.graph_parameters_file is not None or context.service is None:
        return
    context.graph_parameters_file = _new_file(folder, "graph_parameters", ".json")
    context.graph_parameters_file.touch(mode=0o600)  # taken: the next batch has its own
    context.service.hold_graph()
    context.service.schedule([load(context.graph_parameters_file)])


def add_global_parameter_file(context: LaunchContext, path: str) -> None:
    _add(context, GLOBAL_PARAMETERS, ((FILE, path),))


def add_remap(context: LaunchContext, source: str, target: str) -> None:
    _add(context, REMAPS, ((source, target),))


def remaps(context: LaunchContext) -> tuple[tuple[str, str], ...]:
    return context.configurations.get(REMAPS, ())  # type: ignore[return-value]


def namespace(context: LaunchContext) -> str:
    return context.configurations.get(NAMESPACE, "")


def push_namespace(context: LaunchContext, value: str) -> None:
    if value.startswith("/"):
        context.configurations[NAMESPACE] = value.rstrip("/")
    else:
        context.configurations[NAMESPACE] = join_namespace(namespace(context), value)


def join_namespace(outer: str, inner: str) -> str:
    if inner.startswith("/"):
        return inner.rstrip("/") or "/"
    parts = [p for p in (outer.strip("/"), inner.strip("/")) if p]
    return "/" + "/".join(parts) if parts else ""


def check_params_file(path: Path, where: Location | None) -> None:
    """A params file must exist and be valid YAML (errors name its line)."""
    import yaml  # only where a value is read or written: a launch's start needs none

    try:
        text = read_text(path)
    except FileNotFoundError:
        raise ExecutionError(f"parameters file '{path}' does not exist", where) from None
    except OSError as exc:
        raise ExecutionError(f"cannot read parameters file '{path}': {exc.strerror}", where) \
            from None
    try:
        yaml.safe_load(text)
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark
        at = Location(str(path), mark.line + 1, mark.column + 1) if mark else Location(str(path))
        raise ExecutionError(f"parameters file is not valid YAML: {exc.problem}", at) from None


def check_params_text(text: str, path: Path, where: Location | None) -> None:
    """A params file after its substitutions must still be valid YAML."""
    import yaml  # only where a value is read or written: a launch's start needs none

    try:
        yaml.safe_load(text)
    except yaml.MarkedYAMLError as exc:
        raise ExecutionError(f"parameters file '{path}' is not valid YAML after its "
                             f"substitutions (allow_substs): {exc.problem}", where) from None


def write_private_copy(folder: Path, name: str, text: str) -> Path:
    """A params file with its substitutions performed, 0600 in a 0700 folder."""
    path = _new_file(folder, Path(name).stem, Path(name).suffix)
    write_private(path, text)
    return path


def _new_file(folder: Path, stem: str, suffix: str) -> Path:
    """STEM.SUFFIX in the private `folder`, or STEM_2.SUFFIX, … when it is taken."""
    private_folder(folder)
    path = folder / f"{stem}{suffix}"
    count = 1
    while path.exists():
        count += 1
        path = folder / f"{stem}_{count}{suffix}"
    return path


def write_params_file(folder: Path, stem: str, parameters: dict[str, Any],
                      key: str = "/**") -> Path:
    """A params file for the node `key` names (its full name, or /** for any), 0600 in a
    0700 folder: it may hold the robot description."""
    import yaml  # only where a value is read or written: a launch's start needs none

    path = _new_file(folder, stem, ".yaml")
    document = {key: {"ros__parameters": parameters}}
    write_private(path, yaml.safe_dump(document, default_flow_style=False, sort_keys=False,
                                       allow_unicode=True, width=float("inf")))
    return path
