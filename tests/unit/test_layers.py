"""Imports point one way (ARCHITECTURE.md): each layer may import only the ones listed."""

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2] / "launcher"
ALLOWED = {
    "runtime": {"runtime", "errors"},
    "packages": {"packages", "errors"},
    "description": {"description", "runtime", "packages", "errors"},
    "frontend": {"frontend", "description", "runtime", "errors", "compat"},
    "cli": {"cli", "frontend", "description", "runtime", "packages", "errors", "compat", "api",
            "bus", "nodes"},
    "bus": {"bus", "errors", "packages"},
    "sim": {"sim", "bus", "errors", "packages"},
    "nodes": {"nodes", "sim", "bus", "errors", "packages"},
    "compat": {"compat", "api", "packages", "runtime", "errors"},
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


@pytest.mark.parametrize("layer", sorted(ALLOWED))
def test_layer_imports_point_down(layer):
    for path in (ROOT / layer).rglob("*.py"):
        extra = launcher_imports(path) - ALLOWED[layer] - {"__version__"}
        assert not extra, f"{path.relative_to(ROOT)} imports launcher.{sorted(extra)}"


def test_the_launcher_process_modules_avoid_heavy_imports():
    """The cli may name bus modules that run elsewhere (the router); see the import test."""
    heavy = {"mujoco", "numpy", "zenoh", "asyncio"}
    for layer in ("runtime", "frontend", "description", "packages"):
        for path in (ROOT / layer).rglob("*.py"):
            tree = ast.parse(path.read_text())
            for node in ast.walk(tree):
                if isinstance(node, ast.Import | ast.ImportFrom):
                    module = node.module if isinstance(node, ast.ImportFrom) else \
                        node.names[0].name
                    assert (module or "").split(".")[0] not in heavy, path
