"""What each job file of a batch declares, read in a process of its own
(`python -m launcher.cli.batch_inspect`, JSON in on stdin, out on stdout): its kind and its
launch arguments. Apart from the driver, which never loads launch files or test modules (their
imports, the compat shims) beside Ray."""

from __future__ import annotations

import json
import sys
import xml.etree.ElementTree as ElementTree
from pathlib import Path
from typing import Any

from launcher.errors import LaunchError

ROS1_TESTS = (".test", ".launch", ".xml")


def inspect(path: Path, test: bool, package: str | None) -> dict[str, Any]:
    """{kind, arguments, complete, unresolved} of one job file, or {error}."""
    try:
        if test and path.suffix in ROS1_TESTS:
            return _rostest(path)
        if test:
            return _launch_test(path)
        return _launch_file(path, package)
    except LaunchError as exc:
        return {"error": str(exc)}


def _launch_file(path: Path, package: str | None) -> dict[str, Any]:
    from launcher.cli import views
    from launcher.cli.workspace import find_launch_file, load_index
    from launcher.frontend.loader import load_file

    index = load_index()
    if package:
        path = find_launch_file(index, package, str(path))
    description = load_file(path)
    names, unresolved = views.argument_names(description, {}, index)
    return {"kind": "launch", "arguments": names, "complete": not unresolved,
            "unresolved": unresolved}


def _launch_test(path: Path) -> dict[str, Any]:
    text = path.read_text(errors="replace")
    if "generate_test_description" not in text:  # launch_pytest's fixtures: not listable
        return {"kind": "pytest", "arguments": [], "complete": False,
                "unresolved": ["a launch_pytest file: its arguments are not listed"]}
    from launcher import compat
    from launcher.cli import views
    from launcher.cli.workspace import load_index
    from launcher.compat.testing.loader import TestFileError, load_runs
    from launcher.frontend.python_loader import load_module

    compat.enable_in_process()
    module = load_module(path.resolve(), path.stem, "test file")
    try:
        runs = load_runs(module, f"{path.stem}.launch_tests")
        description = runs[0].description(lambda: None)[0]
    except TestFileError as exc:
        raise LaunchError(str(exc)) from None
    description.file = path.resolve()
    names, unresolved = views.argument_names(description, {}, load_index())
    return {"kind": "test", "arguments": names, "complete": not unresolved,
            "unresolved": unresolved}


def _rostest(path: Path) -> dict[str, Any]:
    """A ROS 1 file's `<arg>`s that take a value from outside (a default, or none)."""
    try:
        root = ElementTree.parse(path).getroot()
    except ElementTree.ParseError as exc:
        raise LaunchError(f"{path}: not valid XML: {exc}") from None
    names = [arg.get("name", "") for arg in root.iter("arg")
             if arg.get("value") is None and arg.get("name")]
    includes = bool(list(root.iter("include")))
    return {"kind": "rostest", "arguments": names, "complete": not includes,
            "unresolved": ["an <include> may declare more"] if includes else []}


def main() -> int:
    requests = json.loads(sys.stdin.read())
    answer, sys.stdout = sys.stdout, sys.stderr  # what a test module prints is not the answer
    out = [inspect(Path(r["path"]), r["test"], r.get("package")) for r in requests]
    answer.write(json.dumps(out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
