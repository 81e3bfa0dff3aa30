"""The entry points an ament_python package's `setup.py` declares, read without running it.

    setup(..., entry_points={'console_scripts': ['talker = pkg.talker:main'],
                             'rclpy_components': ['pkg::Talker = pkg.talker:Talker']})

The file is parsed, never executed: `entry_points` is evaluated from literals, names bound at
the file's top level to literals (`package_name = 'pkg'`), `+` of strings, f-strings and
`%`/`.format` on literals. Anything else (a function call, an import) is an error that names
the file, line and column of the part that cannot be read.
"""

from __future__ import annotations

import ast
from pathlib import Path
from typing import Any

from launcher.errors import LaunchError, Location
from launcher.user_files import read_text


class Unreadable(Exception):
    def __init__(self, node: ast.AST, what: str) -> None:
        super().__init__(what)
        self.node = node


def console_scripts(path: Path) -> list[tuple[str, str, int]]:
    """(name, 'module:function', line) for each console script; [] if it declares none."""
    return entry_points(path, "console_scripts")


def entry_points(path: Path, group: str) -> list[tuple[str, str, int]]:
    """(name, 'module:attribute', line) for each entry point of `group`."""
    text = read_text(path)
    try:
        tree = ast.parse(text, str(path))
    except SyntaxError as exc:
        raise LaunchError(f"cannot read setup.py: {exc.msg}",
                          Location(str(path), exc.lineno or 0, exc.offset or 0)) from None
    names: dict[str, ast.AST] = {}
    for statement in tree.body:
        if isinstance(statement, ast.Assign) and len(statement.targets) == 1 \
                and isinstance(statement.targets[0], ast.Name):
            names[statement.targets[0].id] = statement.value
    found: list[tuple[str, str, int]] = []
    for node in ast.walk(tree):
        if not (isinstance(node, ast.Call) and _called(node) in ("setup", "setuptools.setup")):
            continue
        for keyword in node.keywords:
            if keyword.arg != "entry_points":
                continue
            try:
                value = _evaluate(keyword.value, names, 0)
            except Unreadable as problem:
                where = problem.node
                raise LaunchError(
                    f"cannot read setup.py's entry_points without running it: {problem}; "
                    f"write the {group} as literal strings (or declare them in "
                    "setup.cfg's [options.entry_points])",
                    Location(str(path), getattr(where, "lineno", 0),
                             getattr(where, "col_offset", -1) + 1)) from None
            scripts = value.get(group, []) if isinstance(value, dict) else []
            if isinstance(scripts, str):
                scripts = scripts.splitlines()
            for line in scripts:
                if isinstance(line, str) and "=" in line:
                    name, target = (part.strip() for part in line.split("=", 1))
                    found.append((name, target, keyword.value.lineno))
    return found


def _called(node: ast.Call) -> str:
    function = node.func
    if isinstance(function, ast.Name):
        return function.id
    if isinstance(function, ast.Attribute) and isinstance(function.value, ast.Name):
        return f"{function.value.id}.{function.attr}"
    return ""


def _evaluate(node: ast.AST, names: dict[str, ast.AST], depth: int) -> Any:
    if depth > 50:
        raise Unreadable(node, "names refer to each other too deeply")
    if isinstance(node, ast.Constant) and isinstance(node.value, str | int | float | bool):
        return node.value
    if isinstance(node, ast.Dict):
        if any(k is None for k in node.keys):
            raise Unreadable(node, "'**' in a dict")
        return {_evaluate(k, names, depth + 1): _evaluate(v, names, depth + 1)  # type: ignore[arg-type]
                for k, v in zip(node.keys, node.values, strict=True)}
    if isinstance(node, ast.List | ast.Tuple):
        return [_evaluate(item, names, depth + 1) for item in node.elts]
    if isinstance(node, ast.Name):
        if node.id not in names:
            raise Unreadable(node, f"'{node.id}' is not a name set at the file's top level")
        return _evaluate(names[node.id], names, depth + 1)
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
        left, right = _evaluate(node.left, names, depth + 1), \
            _evaluate(node.right, names, depth + 1)
        if type(left) is not type(right) or not isinstance(left, str | list):
            raise Unreadable(node, "'+' of values that are not both strings or lists")
        return left + right
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Mod):
        left = _evaluate(node.left, names, depth + 1)
        right = _evaluate(node.right, names, depth + 1)
        if not isinstance(left, str):
            raise Unreadable(node, "'%' on something that is not a string")
        try:
            return left % (tuple(right) if isinstance(right, list) else right)
        except (TypeError, ValueError) as exc:
            raise Unreadable(node, f"'%' formatting failed: {exc}") from None
    if isinstance(node, ast.JoinedStr):
        parts = []
        for value in node.values:
            if isinstance(value, ast.FormattedValue):
                if value.format_spec is not None or value.conversion != -1:
                    raise Unreadable(value, "a format spec or conversion in an f-string")
                parts.append(str(_evaluate(value.value, names, depth + 1)))
            else:
                parts.append(str(_evaluate(value, names, depth + 1)))
        return "".join(parts)
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) \
            and node.func.attr == "format" and not node.keywords:
        template = _evaluate(node.func.value, names, depth + 1)
        if isinstance(template, str):
            return template.format(*(_evaluate(a, names, depth + 1) for a in node.args))
    raise Unreadable(node, f"a {type(node).__name__.lower()} expression")
