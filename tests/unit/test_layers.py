"""Imports point one way (ARCHITECTURE.md): each layer may import only the ones listed."""

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2] / "launcher"
ALLOWED = {
    "records": set(),
    "schema": {"errors", "records"},
    "private": set(),
    "lineage": set(),
    "user_files": {"errors"},
    "runtime": {"records", "private", "lineage", "runtime", "errors"},
    "packages": {"records", "user_files", "schema", "lineage", "packages", "errors"},
    "description": {"records", "user_files", "private", "lineage", "schema", "description",
                    "runtime", "packages", "errors"},
    "frontend": {"records", "user_files", "private", "schema", "frontend", "description", "runtime",
                 "errors", "compat"},
    "cli": {"records", "user_files", "schema", "cli", "frontend", "description", "runtime",
            "packages", "errors", "compat", "api", "bus", "nodes"},
    "bus": {"records", "user_files", "private", "lineage", "schema", "bus", "errors", "packages"},
    "sim": {"records", "user_files", "schema", "sim", "bus", "errors", "packages"},
    "nodes": {"records", "user_files", "schema", "nodes", "sim", "bus", "errors", "packages"},
    "compat": {"compat", "api", "packages", "runtime", "bus", "errors"},
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


def test_the_launcher_process_modules_avoid_heavy_imports():
    """The cli may name bus modules that run elsewhere (the router); see the import test."""
    heavy = {"mujoco", "numpy", "zenoh", "asyncio"}
    for layer in ("schema", "runtime", "frontend", "description", "packages"):
        for path in layer_files(layer):
            tree = ast.parse(path.read_text())
            for node in ast.walk(tree):
                if isinstance(node, ast.Import | ast.ImportFrom):
                    module = node.module if isinstance(node, ast.ImportFrom) else \
                        node.names[0].name
                    assert (module or "").split(".")[0] not in heavy, path


def _module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT.parent).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _import_graph() -> tuple[dict[str, set[str]], dict[str, set[str]]]:
    """launcher's modules → the launcher modules they import: at module level, and inside
    functions (an explicit `from a.b import c` names the module c when there is one)."""
    modules = {_module_name(p): p for p in ROOT.rglob("*.py")}

    def resolve(name: str) -> str:
        while name and name not in modules:
            name = name.rpartition(".")[0]
        return name

    top: dict[str, set[str]] = {m: set() for m in modules}
    inner: dict[str, set[str]] = {m: set() for m in modules}

    def visit(module: str, node: ast.AST, in_function: bool) -> None:
        for child in ast.iter_child_nodes(node):
            nested = in_function or isinstance(child, ast.FunctionDef | ast.AsyncFunctionDef)
            names: list[str] = []
            if isinstance(child, ast.Import):
                names = [a.name for a in child.names]
            elif isinstance(child, ast.ImportFrom) and child.module and child.level == 0:
                names = [f"{child.module}.{a.name}" for a in child.names]
            for name in (n for n in names if n.startswith("launcher.")):
                found = resolve(name)
                if found and found != module:
                    (inner if nested else top)[module].add(found)
            visit(module, child, nested)

    for module, path in modules.items():
        visit(module, ast.parse(path.read_text()), False)
    return top, inner


def _reachable(start: str, graph: dict[str, set[str]]) -> set[str]:
    seen, stack = set(), [start]
    while stack:
        for found in graph[stack.pop()]:
            if found not in seen:
                seen.add(found)
                stack.append(found)
    return seen


def test_no_module_imports_itself_through_others():
    top, _ = _import_graph()
    cycles = sorted(f"{m} -> {d}" for m in top for d in top[m] if m in _reachable(d, top))
    assert not cycles, "import cycles: " + "; ".join(cycles)


def test_no_import_inside_a_function_dodges_a_cycle():
    """An import placed in a function for start-up time is fine; one that would close a
    cycle at module level is a tangle in disguise."""
    top, inner = _import_graph()
    dodges = sorted(f"{m} -> {d}" for m in inner for d in inner[m] if m in _reachable(d, top))
    assert not dodges, "cycles dodged inside functions: " + "; ".join(dodges)
