"""roslaunch.depends: the packages a launch file needs (its nodes', its includes'), and those
its package's manifest does not declare: what `roslaunch-deps` and rostest's roslaunch check
report. The files are read as launcher reads them (roslaunch.xmlloader)."""

from __future__ import annotations

import os
import sys
from pathlib import Path
from typing import Any

from roslaunch.loader import convert_value  # noqa: F401 (roslaunch.depends has them)
from roslaunch.substitution_args import resolve_args  # noqa: F401

NAME = "roslaunch-deps"


class RoslaunchDepsException(Exception):
    """A launch file whose dependencies cannot be told."""


class RoslaunchDeps:
    """A launch file's dependencies: its nodes (package, type), includes and packages."""

    def __init__(self, nodes: list[Any] | None = None, includes: list[str] | None = None,
                 pkgs: list[str] | None = None) -> None:
        self.nodes, self.includes, self.pkgs = nodes or [], includes or [], pkgs or []

    def __eq__(self, other: object) -> bool:
        return isinstance(other, RoslaunchDeps) and \
            (set(self.nodes), set(self.includes), set(self.pkgs)) == \
            (set(other.nodes), set(other.includes), set(other.pkgs))

    def __repr__(self) -> str:
        return f"nodes: {self.nodes}\nincludes: {self.includes}\npkgs: {self.pkgs}"

    __str__ = __repr__


def _index() -> Any:
    from launcher.packages.index import PackageIndex

    return PackageIndex.from_environment(os.environ)


def _package_of(path: str, index: Any) -> Any:
    """The package whose folder holds `path` (the innermost), or None."""
    where = Path(path).resolve()
    holders = [p for p in index if where.is_relative_to(p.path.resolve())]
    return max(holders, key=lambda p: len(p.path.parts), default=None)


def parse_launch(launch_file: str, file_deps: dict[str, RoslaunchDeps], verbose: bool) -> None:
    """Put `launch_file`'s dependencies (and its includes') in `file_deps`."""
    from roslaunch.config import ROSLaunchConfig
    from roslaunch.core import RLException
    from roslaunch.node_args import loaded
    from roslaunch.xmlloader import XmlLoader

    if verbose:
        print(f"processing launch {launch_file}")
    config = ROSLaunchConfig()
    try:
        XmlLoader().load(launch_file, config, argv=sys.argv, verbose=False)
        files = [str(f) for f in loaded([launch_file]).files]
    except RLException as exc:
        raise RoslaunchDepsException(f"invalid launch file {launch_file}: {exc}") from None
    index = _index()
    includes = [f for f in files if Path(f).resolve() != Path(launch_file).resolve()]
    nodes = [(n.package, n.type) for n in config.nodes + config.tests]
    pkgs = {package for package, _ in nodes}
    pkgs.update(p.name for p in (_package_of(f, index) for f in includes) if p is not None)
    file_deps[launch_file] = RoslaunchDeps(nodes, includes, sorted(pkgs))


def rl_file_deps(file_deps: dict[str, RoslaunchDeps], launch_file: str,
                 verbose: bool = False) -> None:
    """Put `launch_file`'s dependencies in `file_deps`."""
    parse_launch(launch_file, file_deps, verbose)


def fullusage() -> None:
    """Print roslaunch-deps' usage."""
    print(f"Usage:\n\t{NAME} [options] <file-or-package>\n")


def print_deps(base_pkg: str, file_deps: dict[str, RoslaunchDeps], verbose: bool) -> None:
    """Print the packages the files need."""
    if verbose:
        for deps in file_deps.values():
            for package, node_type in deps.nodes:
                print(f"{package} [{package}/{node_type}]")
        print("-" * 80)
    print(" ".join(sorted({p for deps in file_deps.values() for p in deps.pkgs})))


def calculate_missing(base_pkg: str, missing: dict[str, set[str]],
                      file_deps: dict[str, RoslaunchDeps],
                      use_test_depends: bool = False) -> dict[str, set[str]]:
    """Add to `missing` ({package: packages}) what each file's package needs and does not
    declare in its manifest."""
    index = _index()
    for launch_file, deps in file_deps.items():
        package = _package_of(launch_file, index)
        if package is None:
            print(f"ERROR: cannot determine package for [{launch_file}]", file=sys.stderr)
            continue
        declared = set(package.run_dependencies()) | {package.name}
        if use_test_depends:
            declared |= set(package.dependencies.get("test_depend", []))
        missing.setdefault(package.name, set()).update(set(deps.pkgs) - declared)
    return missing


def roslaunch_deps(files: list[str], verbose: bool = False, use_test_depends: bool = False,
                   ignore_unset_args: bool = False) -> tuple[str | None, dict[str, Any],
                                                             dict[str, set[str]]]:
    """(the files' package, {file: RoslaunchDeps}, {package: missing dependencies})."""
    file_deps: dict[str, RoslaunchDeps] = {}
    index = _index()
    base = {getattr(_package_of(f, index), "name", None) for f in files}
    if len(base) > 1:
        raise RoslaunchDepsException("roslaunch files must be in the same package: "
                                     + ", ".join(files))
    for launch_file in files:
        if not os.path.exists(launch_file):
            raise RoslaunchDepsException(f"roslaunch file [{launch_file}] does not exist")
        parse_launch(launch_file, file_deps, verbose)
    base_pkg = next(iter(base), None)
    return base_pkg, file_deps, calculate_missing(base_pkg or "", {}, file_deps,
                                                  use_test_depends)


def roslaunch_deps_main(argv: list[str] = sys.argv) -> None:  # noqa: B006 (roslaunch's)
    """`roslaunch-deps [--warn] [-v] FILE…`: print the packages the files need (--warn:
    and those their manifest misses)."""
    words = argv[1:]
    verbose, warn = "-v" in words, "--warn" in words
    files = [w for w in words if not w.startswith("-")]
    if not files:
        fullusage()
        sys.exit(1)
    try:
        base_pkg, file_deps, missing = roslaunch_deps(files, verbose)
    except RoslaunchDepsException as exc:
        print(str(exc), file=sys.stderr)
        sys.exit(1)
    print_deps(base_pkg or "", file_deps, verbose)
    if warn:
        for package, names in missing.items():
            if names:
                print(f"Missing declarations in [{package}/package.xml]:\n  " +
                      "\n  ".join(sorted(names)))
