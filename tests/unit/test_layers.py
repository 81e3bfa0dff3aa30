"""Imports point one way (docs/reference/layout.md, "Layers"): each layer may import only the
ones listed; and the layout page names every package and top-level module."""

import ast
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2] / "launcher"
ALLOWED = {
    "records": set(),
    "machines": set(),
    "lifecycle": {"machines"},
    "schema": {"errors", "records"},
    "private": set(),
    "dispositions": set(),
    "lineage": {"dispositions"},
    "user_files": {"errors"},
    "arguments": {"errors"},
    "runtime": {"records", "private", "lineage", "dispositions", "runtime", "errors",
                "lifecycle"},
    "packages": {"records", "user_files", "schema", "lineage", "packages", "errors"},
    "description": {"records", "user_files", "private", "lineage", "schema", "description",
                    "runtime", "packages", "errors", "lifecycle"},
    "frontend": {"records", "user_files", "private", "schema", "frontend", "description", "runtime",
                 "errors", "compat"},
    "cli": {"records", "user_files", "schema", "arguments", "cli", "frontend", "description", "runtime",
            "packages", "errors", "compat", "api", "bus", "nodes", "control", "lifecycle",
            "batch"},
    # launcher batch: the batch file, its jobs, the job host, Ray and the reports; the job
    # host reuses the launch's process helpers (lineage, the watchdog)
    "batch": {"batch", "records", "errors", "schema", "user_files", "private", "lineage",
              "dispositions", "runtime"},
    "bus": {"records", "user_files", "private", "lineage", "schema", "arguments", "bus", "errors",
            "packages", "machines"},
    "control": {"records", "schema", "control", "bus", "errors", "lifecycle"},
    "sim": {"records", "user_files", "schema", "sim", "control", "bus", "errors", "packages"},
    "nodes": {"records", "user_files", "schema", "arguments", "nodes", "sim", "control", "bus",
              "errors", "packages"},
    "api": {"api", "records", "description", "runtime", "frontend", "packages", "errors",
            "lifecycle"},
    # the shims' entry points (launch.LaunchService, launch_testing's runner, roslaunch's
    # ROSLaunchParent) build a launch as `launcher launch` does: through the cli's set-up
    "compat": {"compat", "api", "records", "description", "frontend", "cli", "packages",
               "runtime", "bus", "errors", "lifecycle", "machines"},
}


def launcher_imports(path: Path) -> set[str]:
    tree = ast.parse(path.read_text())
    found = set()
    for node in ast.walk(tree):
        names = []
        if isinstance(node, ast.Import):
            names = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            names = [node.module] + [f"{node.module}.{a.name}" for a in node.names]
        for name in names:
            parts = name.split(".")
            if parts[0] == "launcher" and len(parts) > 1:
                found.add(parts[1])
    return found


def layer_files(layer: str) -> list[Path]:
    """A layer's modules: a package folder, or one module (schema.py)."""
    single = ROOT / f"{layer}.py"
    return [single] if single.exists() else sorted((ROOT / layer).rglob("*.py"))


@pytest.mark.parametrize("layer", sorted(ALLOWED))
def test_layer_imports_point_down(layer):
    files = layer_files(layer)
    assert files, layer
    for path in files:
        extra = launcher_imports(path) - ALLOWED[layer] - {"__version__"}
        assert not extra, f"{path.relative_to(ROOT)} imports launcher.{sorted(extra)}"


def _module_level(tree: ast.AST) -> list[ast.AST]:
    """The nodes run when a module is imported (not those inside its functions, which
    import what they need when called)."""
    found, todo = [], [tree]
    while todo:
        node = todo.pop()
        found.append(node)
        todo += [child for child in ast.iter_child_nodes(node)
                 if not isinstance(child, ast.FunctionDef | ast.AsyncFunctionDef)]
    return found


def test_the_launcher_process_modules_avoid_heavy_imports():
    """Not at import time: the launcher's start-up. The cli may name bus modules that run
    elsewhere (the router); see the import test."""
    heavy = {"mujoco", "numpy", "zenoh", "asyncio"}
    for layer in ("schema", "runtime", "frontend", "description", "packages"):
        for path in layer_files(layer):
            tree = ast.parse(path.read_text())
            for node in _module_level(tree):
                if isinstance(node, ast.Import | ast.ImportFrom):
                    module = node.module if isinstance(node, ast.ImportFrom) else \
                        node.names[0].name
                    assert (module or "").split(".")[0] not in heavy, path


def _module_name(path: Path, root: Path) -> str:
    parts = list(path.relative_to(root.parent).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _imported(module: str, package: str, node: ast.AST) -> list[str]:
    """The module names an import statement names (relative ones made absolute): for `from
    a.b import c`, a.b.c where c is a module, else a.b."""
    if isinstance(node, ast.Import):
        return [a.name for a in node.names]
    if not isinstance(node, ast.ImportFrom):
        return []
    base = node.module or ""
    if node.level:
        anchor = package
        for _ in range(node.level - 1):
            anchor = anchor.rpartition(".")[0]
        base = f"{anchor}.{base}" if base else anchor
    return [f"{base}.{a.name}" for a in node.names]


def import_graph(root: Path = ROOT) -> dict[str, set[str]]:
    """Each module of the package at `root` → the modules of it that it imports, wherever
    the import stands: at module level, inside a function, under `if TYPE_CHECKING:`."""
    modules = {_module_name(p, root): p for p in root.rglob("*.py")}

    def resolve(name: str) -> str:
        while name and name not in modules:
            name = name.rpartition(".")[0]
        return name

    graph: dict[str, set[str]] = {m: set() for m in modules}
    for module, path in modules.items():
        package = module if path.name == "__init__.py" else module.rpartition(".")[0]
        for node in ast.walk(ast.parse(path.read_text())):
            for name in _imported(module, package, node):
                found = resolve(name)
                if found and found != module:
                    graph[module].add(found)
    return graph


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The import cycles: each set of modules that import one another (Tarjan's strongly
    connected components of more than one module)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    found: list[list[str]] = []

    def visit(module: str) -> None:
        index[module] = low[module] = len(index)
        stack.append(module)
        for other in sorted(graph[module]):
            if other not in index:
                visit(other)
                low[module] = min(low[module], low[other])
            elif other in stack:
                low[module] = min(low[module], index[other])
        if low[module] == index[module]:
            component = []
            while True:
                other = stack.pop()
                component.append(other)
                if other == module:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for module in sorted(graph):
        if module not in index:
            visit(module)
    return found


def test_no_module_imports_itself_through_others():
    """No import cycle anywhere in launcher/, counting every import: one placed inside a
    function (for start-up time, or to dodge a cycle) or under TYPE_CHECKING is an edge too."""
    found = cycles(import_graph())
    assert not found, "import cycles: " + "; ".join(" <-> ".join(c) for c in found)


SHIM_PACKAGES = sorted(path for kind in ("nodes", "shims")
                       for path in (ROOT / "compat" / kind).iterdir()
                       if (path / "__init__.py").exists())


@pytest.mark.parametrize("package", SHIM_PACKAGES,
                         ids=[f"{p.parent.name}/{p.name}" for p in SHIM_PACKAGES])
def test_no_shim_module_imports_itself_through_others(package):
    """Inside each shim package too (compat/nodes/rclpy/, compat/shims/launch/, …): its modules
    import one another by the real package's names (`from rclpy.node import Node`), which are
    not launcher's, so the check above does not see them; here `<package>.x` is the package's
    own module x, as the import hook (compat/finder.py) makes it."""
    found = cycles(import_graph(package))
    assert not found, "import cycles: " + "; ".join(" <-> ".join(c) for c in found)


def test_the_cycle_check_sees_imports_inside_functions_and_type_checking(tmp_path):
    """The check itself: a cycle closed only inside a function, or only under TYPE_CHECKING,
    or through a relative import, is found."""
    package = tmp_path / "pkg"
    package.mkdir()
    (package / "__init__.py").write_text("")
    (package / "a.py").write_text("from pkg import b\n")
    (package / "b.py").write_text("def f():\n    from pkg.a import thing\n")
    (package / "c.py").write_text("from typing import TYPE_CHECKING\n"
                                  "if TYPE_CHECKING:\n    from . import d\n")
    (package / "d.py").write_text("import pkg.c\n")
    (package / "e.py").write_text("import pkg.a\n")
    assert cycles(import_graph(package)) == [["pkg.a", "pkg.b"], ["pkg.c", "pkg.d"]]


def test_the_cycle_check_reads_a_shim_package_by_its_own_names(tmp_path):
    """A shim package (a folder of compat/, named as the real package) is read as that
    package: `rclpy.x` is its module x, and names of other packages are not its own."""
    package = tmp_path / "rclpy"
    package.mkdir()
    (package / "__init__.py").write_text("")
    (package / "node.py").write_text("import rclpy.executors\nfrom launcher.bus import keys\n")
    (package / "executors.py").write_text("def f():\n    from rclpy.node import Node\n")
    (package / "qos.py").write_text("from std_msgs.msg import String\nimport rclpy\n")
    assert cycles(import_graph(package)) == [["rclpy.executors", "rclpy.node"]]


LAYOUT = ROOT.parent / "docs" / "reference" / "layout.md"


def test_the_layout_page_names_every_package_and_top_level_module():
    """A newcomer finds every folder of launcher/ (two levels down; the built-in packages and
    the compat shims are named by their parent) and every top-level module on the page."""
    page = LAYOUT.read_text()
    parts = [f"{path.relative_to(ROOT).as_posix()}/" for path in sorted(ROOT.glob("*/"))
             if path.is_dir() and path.name != "__pycache__"]
    parts += [f"{path.relative_to(ROOT).as_posix()}/" for path in sorted(ROOT.glob("*/*/"))
              if path.is_dir() and path.name != "__pycache__" and
              path.parent.name not in ("builtin", "compat")]
    parts += [path.name for path in sorted(ROOT.glob("*.py"))
              if path.name not in ("__init__.py", "__main__.py")]
    missing = [part for part in parts
               if not re.search(rf"(launcher/|[\s(]){re.escape(part)}", page)]
    assert not missing, f"{LAYOUT} does not name: {missing}"


def test_no_test_module_imports_another():
    """What several test modules (and benchmarks) share lives in tests/support/, not in one
    of the test modules."""
    tests = ROOT.parent / "tests"
    found = [f"{path.relative_to(ROOT.parent)}: {name}"
             for path in sorted([*tests.rglob("test_*.py"), *(ROOT.parent / "bench").glob("*.py")])
             for name in sorted(n for n in imports_from_tests(path)
                                if n.split(".")[-1].startswith("test_"))]
    assert not found, "test modules importing test modules:\n" + "\n".join(found)


def imports_from_tests(path: Path) -> set[str]:
    """Every module `path` imports from the tests package."""
    found = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom) and node.module and node.module.startswith("tests"):
            found.add(node.module)
        elif isinstance(node, ast.Import):
            found.update(a.name for a in node.names if a.name.startswith("tests"))
    return found


def _imports_anywhere(path: Path) -> set[str]:
    """The top-level names of every module `path` imports, wherever the import stands."""
    found = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            found |= {a.name.split(".")[0] for a in node.names}
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            found.add(node.module.split(".")[0])
    return found


@pytest.mark.parametrize(("library", "allowed"), [
    ("ray", {"batch/cluster.py", "batch/task.py"}),
    ("matplotlib", {"batch/picture.py", "cli/plot_command.py"}),
], ids=["ray", "matplotlib"])
def test_a_heavy_optional_library_is_imported_by_its_own_modules_alone(library, allowed):
    """Ray (the cluster extra) and matplotlib (the plot extra) are optional: only the modules
    that need them import them, so every other command runs without them."""
    importers = {str(p.relative_to(ROOT)) for p in ROOT.rglob("*.py")
                 if library in _imports_anywhere(p)}
    assert importers <= allowed, sorted(importers - allowed)


def test_the_job_host_imports_nothing_heavy():
    """Every job of a batch pays for the job host's imports."""
    import subprocess
    import sys

    heavy = ("ray", "yaml", "zenoh", "mujoco", "numpy")
    done = subprocess.run([sys.executable, "-c", "import sys, launcher.batch.host; print(' '.join("
                           f"m for m in {heavy!r} if m in sys.modules))"],
                          capture_output=True, text=True, check=True)
    assert done.stdout.strip() == ""
