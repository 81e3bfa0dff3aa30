"""A private name (`_x`) is used only by the module that defines it: no module imports another's
private names or reads them off another module's objects. What one module needs of another is
its public surface (the compat layer's rclpy and rospy included: they use the bus node's
public methods, and the rclpy package's modules the few functions node.py, task.py and timer.py
offer them).

Read from the source: an `import` of a name that starts with one underscore, and every
`x._name` whose `x` is not `self`/`cls`/`super()` and whose module neither defines `_name` nor
assigns it. The exceptions are other libraries' own conventions, listed with their reasons."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2] / "launcher"

# Other libraries' names that are theirs to offer, used as their documentation says
LIBRARY_NAMES = {
    "_exit": "os._exit: ending a forked child or a stuck process without its exit hooks",
    "_getframe": "sys._getframe: the caller's file and line in a log record, as rospy's",
    "_SubParsersAction": "argparse's type of add_subparsers(), for annotations",
    "_actions": "argparse: a parser's arguments, read to print them in ROS's layout",
    "_make": "namedtuple's constructor from an iterable (its documented API)",
    "_replace": "namedtuple's and a dataclass field's copy with changes (documented API)",
}
# Third-party internals that launcher patches or must call, each in one place with the reason
PATCHED = {
    ("packages/xacro.py", "_eval_dict"): "xacro's $(find) table, pointed at the package index",
    ("compat/testing/launch_pytest/plugin.py", "_genfunctions"):
        "pytest's making of a test's items (one per parameter), for the coroutine and generator "
        "tests launch_pytest collects, as launch_pytest's own plugin does",
    ("runtime/warm_server.py", "_run_module_as_main"):
        "what CPython's `python -m` itself calls: a module started warm runs as it does cold, "
        "the frames of its traceback included",
    ("runtime/warm_server.py", "_run_exitfuncs"):
        "the exit handlers CPython runs before it ends by SIGINT after an uncaught "
        "KeyboardInterrupt, which a warm-started process must run as it would cold",
}


def private_uses(path: Path, relative: str) -> list[tuple[int, str]]:
    """(line, what) of each private name of another module that `path` uses; `relative` is its
    path below launcher/ (the PATCHED table's key)."""
    tree = ast.parse(path.read_text())
    defined: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            defined.add(node.name)
        elif isinstance(node, ast.Attribute) and isinstance(node.ctx, ast.Store):
            defined.add(node.attr)
        elif isinstance(node, ast.Name) and isinstance(node.ctx, ast.Store):
            defined.add(node.id)
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            found += [(node.lineno, f"from {node.module} import {alias.name}")
                      for alias in node.names if is_private(alias.name)]
        elif isinstance(node, ast.Attribute) and is_private(node.attr):
            owner = node.value
            if isinstance(owner, ast.Name) and owner.id in ("self", "cls"):
                continue
            if isinstance(owner, ast.Call) and isinstance(owner.func, ast.Name) and \
                    owner.func.id == "super":
                continue
            if node.attr in defined or node.attr in LIBRARY_NAMES:
                continue
            if (relative, node.attr) in PATCHED:
                continue
            found.append((node.lineno, ast.unparse(node)))
    return found


def is_private(name: str) -> bool:
    return name.startswith("_") and not name.startswith("__")


@pytest.mark.parametrize("part", sorted(p.name for p in ROOT.iterdir()
                                        if p.name != "__pycache__" and
                                        (p.is_dir() or p.suffix == ".py")))
def test_no_module_uses_another_modules_private_names(part):
    top = ROOT / part
    uses = [f"{path.relative_to(ROOT)}:{line}: {text}"
            for path in (sorted(top.rglob("*.py")) if top.is_dir() else [top])
            for line, text in private_uses(path, path.relative_to(ROOT).as_posix())]
    assert not uses, "private names of other modules:\n" + "\n".join(uses)


def test_the_check_finds_a_private_import(tmp_path):
    module = tmp_path / "m.py"
    module.write_text("from launcher.nodes.conversions import _hidden\n"
                      "def f(node):\n    return node._bus\n")
    assert [text for _, text in private_uses(module, "m.py")] == \
        ["from launcher.nodes.conversions import _hidden", "node._bus"]

