"""A node's `param` entries (launch_ros's and roslaunch's forms) and how they become the
values and params files a node is given: one group per entry, launch_ros's typing, roslaunch's
`<rosparam>` YAML, and the Python API's dicts."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from launcher.description import parameters as params
from launcher.description.condition import entry_applies, if_attr, unless_attr
from launcher.description.fields import Kind, attr, resolve
from launcher.description.substitution import Text_, perform_text, to_text
from launcher.errors import ExecutionError
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext
from launcher.user_files import read_text


@dataclass(eq=False)
class ParamEntry:
    name: Text_ | None = attr(Kind.TEXT, doc="Parameter name (dotted for nested ones).")
    value: Any = attr(Kind.VALUE, doc="Its value: one, or a list.")
    type: Any = attr(Kind.TEXT, choices=params.TYPES,
                     doc="str, int, float, bool, list_of_str|int|float|bool or yaml; default: "
                         "as launch_ros types the value.")
    separator: Any = attr(Kind.NAME, name="value-sep", aliases=("value_sep",),
                          doc="Split the value at this text into a list.")
    from_file: Text_ | None = attr(Kind.TEXT, name="from", doc="A params YAML file to load.")
    allow_substs: Any = attr(Kind.BOOL, doc="With 'from' or a rosparam: substitutions in "
                                            "the file are performed (default false).")
    command: Text_ | None = attr(Kind.TEXT, doc="roslaunch's: the value is this command's "
                                                "output.")
    textfile: Text_ | None = attr(Kind.TEXT, doc="roslaunch's: the value is this file's text.")
    rosparam_file: Text_ | None = attr(Kind.TEXT, doc="roslaunch's rosparam: a YAML map of "
                                                      "parameters.")
    rosparam: Text_ | None = attr(Kind.TEXT, doc="roslaunch's rosparam: the YAML, inline.")
    children: list[Any] = attr(Kind.ENTRIES, name="param", doc="Nested parameters.")
    only_if: Any = if_attr()
    only_unless: Any = unless_attr()
    group: bool = False  # a Python dict: one group of named children, one params file
    where: Any = None  # where the entry is written, for its errors

    def __post_init__(self) -> None:
        if self.value is None:
            self.value = params.ros1_value(self.command, self.textfile)


_spec = ParamEntry.__dataclass_fields__["children"]
_spec.metadata = {"launch": _spec.metadata["launch"]._replace(entry=ParamEntry)}  # self-nesting



def params_folder(context: LaunchContext) -> Path:
    """Where the params files launcher writes for a run go (private: they may hold the robot
    description)."""
    if context.log_dir:
        return Path(context.log_dir) / "params"
    import tempfile  # (a run without a log folder alone: start-up time)

    return Path(tempfile.gettempdir()) / f"launcher-params-{os.getuid()}"


def parameter_groups(context: LaunchContext, entries: list[ParamEntry],
                     where: Any) -> list[Path | dict[str, Any]]:
    """A node's own parameters as launch_ros groups them: each `param` entry (a Python dict)
    is one group of values; each `from` is its file."""
    groups: list[Path | dict[str, Any]] = []
    for entry in entries:
        if not entry_applies(context, entry):
            continue
        if entry.from_file is not None:
            groups.append(_from_file(context, entry, entry.where or where))
            continue
        if entry.allow_substs is not None and entry.rosparam_file is None and \
                entry.rosparam is None:
            raise ExecutionError("param: 'allow_substs' goes with 'from' (a params file)",
                                 entry.where or where)
        values: dict[str, Any] = {}
        for child in entry.children if entry.group else [entry]:
            _collect(context, child, "", values, entry.where or where)
        groups.append(values)
    return groups


def gather_parameters(context: LaunchContext, entries: list[ParamEntry],
                      where: Any) -> tuple[list[Path], dict[str, Any]]:
    """(params files, values) for a composable node: the launch's `set_parameters_from_file`s
    and `set_parameter`s, then its own entries."""
    files: list[Path] = []
    inline: dict[str, Any] = {}
    for name, value in params.global_settings(context):
        if name == params.FILE:
            files.append(Path(value))
        else:
            inline[name] = value
    for group in parameter_groups(context, entries, where):
        if isinstance(group, dict):
            inline.update(group)
        else:
            files.append(group)
    return files, inline


def _from_file(context: LaunchContext, entry: ParamEntry, where: Any) -> Path:
    if entry.name is not None:
        raise ExecutionError("param: give either 'name' or 'from', not both", where)
    path = Path(perform_text(context, entry.from_file))
    params.check_params_file(path, where)
    if entry.allow_substs is None or not resolve(context, entry.allow_substs, Kind.BOOL,
                                                 "param.allow_substs"):
        return path
    if context.parse_text is None:
        raise ExecutionError("this run cannot read substitutions in files", where)
    text = context.parse_text(read_text(path), str(path))
    performed = perform_text(context, text)
    params.check_params_text(performed, path, where)
    return params.write_private_copy(params_folder(context), path.name, performed)


def _collect(context: LaunchContext, entry: ParamEntry, outer: str, out: dict[str, Any],
             where: Any) -> None:
    if entry.rosparam_file is not None or entry.rosparam is not None:
        out.update(rosparam_entry(context, entry, outer, where))
        return
    if entry.name is None:
        raise ExecutionError("param: each parameter needs 'name' (or 'from' a file)", where)
    if entry.from_file is not None:
        raise ExecutionError("param: give either 'name' or 'from', not both", where)
    name = f"{outer}{perform_text(context, entry.name)}"
    kind = resolve(context, entry.type, Kind.TEXT, "param.type") if entry.type else None
    if entry.children:
        if entry.value is not None:
            raise ExecutionError(f"param '{name}': give either 'value' or nested 'param' "
                                 "entries, not both", where)
        if kind is not None:
            raise ExecutionError(f"param '{name}': 'type' goes with 'value', not with nested "
                                 "'param' entries", where)
        for child in entry.children:
            _collect(context, child, f"{name}.", out, child.where or where)
        return
    if entry.value is None:
        raise ExecutionError(f"param '{name}' needs a 'value' (or nested 'param' entries)",
                             where)
    try:
        value = params.value_of(context, entry.value, kind, name, entry.separator)
    except ExecutionError as exc:
        raise exc if exc.location else exc.at(where) from None
    out.update(params.unrolled(name, value))  # (roslaunch's yaml maps: their parameters)


def rosparam_entry(context: LaunchContext, entry: Any, outer: str,
                   where: Any) -> dict[str, Any]:
    """roslaunch's `<rosparam>`: the parameters of its YAML (a file, or inline)."""
    prefix = outer + (perform_text(context, entry.name) if entry.name is not None else "")
    substitute = entry.allow_substs is not None and resolve(
        context, entry.allow_substs, Kind.BOOL, "subst_value")
    if entry.rosparam_file is not None:
        path = Path(perform_text(context, entry.rosparam_file))
        params.check_params_file(path, where)
        text = read_text(path)
        at = path
    else:
        text = perform_text(context, entry.rosparam)
        at = None
    try:
        return params.rosparam_values(context, text, prefix.strip("/"), where, substitute)
    except ExecutionError as exc:
        raise ExecutionError(f"{exc.message} (in {at})" if at else exc.message,
                             exc.location) from None


def python_parameters(values: list[Any]) -> list[ParamEntry]:
    """The Python API's `parameters=[{'a': 1}, 'file.yaml']` as entries: a dict is one group,
    its str values strings, its substitutions typed by YAML's rules (as in launch_ros)."""
    entries: list[ParamEntry] = []
    for value in values:
        if isinstance(value, ParamEntry):
            entries.append(value)
        elif isinstance(value, dict):
            entries.append(ParamEntry(children=_python_dict(value), group=True))
        else:
            entries.append(ParamEntry(from_file=to_text(value)))
    return entries


def _python_dict(values: dict[Any, Any]) -> list[ParamEntry]:
    entries = []
    for name, item in values.items():
        if isinstance(item, dict):
            entries.append(ParamEntry(name=to_text(name), children=_python_dict(item)))
        else:
            entries.append(python_parameter(name, item))
    return entries


def python_parameter(name: Any, value: Any, kind: str | None = None) -> ParamEntry:
    """One parameter from Python values (launch_ros's ParameterValue gives `kind`)."""
    written: Any = [params.python_value(v) for v in value] \
        if isinstance(value, list | tuple) else params.python_value(value)
    return ParamEntry(name=to_text(name), value=written, type=kind and to_text(kind))
