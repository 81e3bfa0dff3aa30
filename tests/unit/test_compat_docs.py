"""The compat layer's public surface is documented, as rclpy documents its own: every public
method and function of the modules the docs' Python API page shows says what it does (the
list, docs/_gen/reference_python.py's, grows until it holds the whole surface)."""

from __future__ import annotations

import ast
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "docs" / "_gen"))
import reference_python  # noqa: E402

NODES = Path(__file__).resolve().parents[2] / "launcher" / "compat" / "nodes"
DOCUMENTED = reference_python.MODULES


def undocumented(path: Path) -> list[str]:
    tree = ast.parse(path.read_text())
    found = []
    for node in tree.body:
        if isinstance(node, ast.FunctionDef) and not node.name.startswith("_") and \
                ast.get_docstring(node) is None:
            found.append(node.name)
        if isinstance(node, ast.ClassDef) and not node.name.startswith("_"):
            found += [f"{node.name}.{f.name}" for f in node.body
                      if isinstance(f, ast.FunctionDef | ast.AsyncFunctionDef) and
                      not f.name.startswith("_") and ast.get_docstring(f) is None]
    return found


@pytest.mark.parametrize("module", DOCUMENTED)
def test_every_public_method_says_what_it_does(module):
    assert undocumented(NODES / module) == []
