"""The suite's own layout: helpers live in tests/support/ alone, and conftest.py files hold
fixtures and hooks only, so no test module imports from a conftest (pytest advises against
it: a conftest is loaded by pytest's own rules, not as a module of the package)."""

from __future__ import annotations

import ast
from pathlib import Path

TESTS = Path(__file__).resolve().parents[1]


def _imported_modules(path: Path) -> set[str]:
    found = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom) and node.module:
            found.add(node.module)
        elif isinstance(node, ast.Import):
            found.update(alias.name for alias in node.names)
    return found


def test_no_test_module_imports_from_a_conftest():
    offenders = [str(path.relative_to(TESTS)) for path in sorted(TESTS.rglob("*.py"))
                 if any(module.split(".")[-1] == "conftest"
                        for module in _imported_modules(path))]
    assert not offenders, offenders


def test_conftest_files_define_fixtures_and_hooks_only():
    """What a conftest defines at its top level: fixtures, pytest hooks (pytest_*) and
    private names; a public helper function or class belongs in tests/support/."""
    for path in TESTS.rglob("conftest.py"):
        for node in ast.parse(path.read_text()).body:
            if not isinstance(node, ast.FunctionDef | ast.ClassDef):
                continue
            fixture = any("fixture" in ast.unparse(d) for d in getattr(node, "decorator_list", []))
            assert fixture or node.name.startswith(("pytest_", "_")), \
                f"{path.relative_to(TESTS)}: {node.name} is a helper: put it in tests/support/"
