"""A package's executables: what `node` and `$(exec-in-pkg)` can run.

  * executable files in `lib/<pkg>/`, `lib/`, `scripts/` and `bin/` of the package, and for
    a package of an install (AMENT_PREFIX_PATH) in `<prefix>/lib/<pkg>/`, where ROS 2 puts
    them;
  * Python entry points, declared in package.xml as
        <export><executable name="driver" module="robot_application.driver:main"/></export>
    or in setup.cfg's `[options.entry_points] console_scripts` (as ament_python packages do).
    They run as `python -m launcher.packages.entry MODULE:FUNCTION`, with the package folder
    on PYTHONPATH; the function is found by import, never by evaluating text;
  * for a compiled package found only as source, launcher's own implementation's first (its
    stand-in, see index.py), then any the source holds.
"""

from __future__ import annotations

import os
import re
import sys
from pathlib import Path
from typing import Any

from launcher.errors import LaunchError, did_you_mean
from launcher.packages.manifest import Package
from launcher.records import dataclass, field

_ENTRY = re.compile(r"^[A-Za-z_][\w.]*:[A-Za-z_][\w.]*$")


@dataclass(frozen=True)
class Executable:
    name: str
    argv: tuple[str, ...]  # the command to run it, before its own arguments
    path: Path | None = None  # the file, for file executables
    pythonpath: tuple[str, ...] = field(default=())  # folders its module needs
    runnable: bool = True  # False: a file without the executable bit

    def environment(self, env: dict[str, str]) -> dict[str, str]:
        if not self.pythonpath:
            return env
        old = env.get("PYTHONPATH", "")
        return {**env, "PYTHONPATH": os.pathsep.join([*self.pythonpath, *([old] if old else [])])}


def executables(package: Package) -> dict[str, Executable]:
    own = _own_executables(package)
    if package.stand_in is None:
        return own
    return {**own, **executables(package.stand_in)}


def _own_executables(package: Package) -> dict[str, Executable]:
    found: dict[str, Executable] = {}
    folders = [package.path / "lib" / package.name, package.path / "lib",
               package.path / "scripts", package.path / "bin"]
    if package.origin == "ament" and package.prefix is not None:  # an install: where ROS 2
        folders.insert(0, package.prefix / "lib" / package.name)  # puts its executables
    for folder in folders:
        try:
            entries = sorted(os.scandir(folder), key=lambda e: e.name)
        except OSError:
            continue
        for entry in entries:
            if entry.is_file() and not entry.name.startswith((".", "_")) \
                    and entry.name not in found:
                found[entry.name] = _file_executable(Path(entry.path))
    for name, target in _declared_entry_points(package):
        found.setdefault(name, Executable(
            name, (sys.executable, "-m", "launcher.packages.entry", target),
            pythonpath=(str(package.path),)))
    return found


def _file_executable(path: Path) -> Executable:
    if _python_script(path):
        return Executable(path.name, (sys.executable, str(path)), path)
    return Executable(path.name, (str(path),), path, runnable=os.access(path, os.X_OK))


def _python_script(path: Path) -> bool:
    """Whether to run it with launcher's interpreter (see the module's text)."""
    try:
        with open(path, "rb") as handle:
            first = handle.readline(256).strip()
    except OSError:
        return False
    if first.startswith(b"#!"):
        words = first[2:].split()
        return bool(words[:2] == [b"/usr/bin/env", b"python"] or words[:1] == [b"/usr/bin/python"])
    return path.suffix == ".py"


def find_executable(package: Package, name: str) -> Executable:
    found = lookup(package, "executable", name, executables(package), "it has")
    if not found.runnable:
        raise LaunchError(f"'{found.path}' in package '{package.name}' is not executable; "
                          f"make it so with: chmod +x {found.path}")
    return found


def lookup(package: Package, kind: str, name: str, available: dict[str, Any],
           listed: str) -> Any:
    """`available[name]`, or an error naming what is close and all there is."""
    found = available.get(name)
    if found is None:
        listing = ", ".join(sorted(available)) or "none"
        raise LaunchError(f"package '{package.name}' has no {kind} '{name}'"
                          f"{did_you_mean(name, available)}; {listed}: {listing}")
    return found


def _declared_entry_points(package: Package) -> list[tuple[str, str]]:
    return declared(package, "executable", "console_scripts")


def declared(package: Package, tag: str, group: str, key: str = "name") -> list[tuple[str, str]]:
    """(name, 'module:attribute') pairs a package declares: package.xml's
    `<export><TAG KEY=… module=…/>`, then the entry-point GROUP of setup.cfg and setup.py."""
    found = [(e.get(key, ""), e.get("module", "")) for e in package.exports.get(tag, [])]
    setup_cfg = package.path / "setup.cfg"
    if setup_cfg.is_file():
        import configparser  # (setup.cfg alone: start-up time)

        parser = configparser.ConfigParser(delimiters=("=",))
        parser.optionxform = str  # type: ignore[assignment,method-assign]  # keep the case
        try:
            parser.read(setup_cfg)
            lines = parser.get("options.entry_points", group, fallback="")
        except configparser.Error:
            lines = ""
        for line in lines.splitlines():
            if "=" in line:
                name, target = (part.strip() for part in line.split("=", 1))
                found.append((name, target))
    setup_py = package.path / "setup.py"
    if setup_py.is_file():
        from launcher.packages.setup_py import entry_points

        found += [(name, target) for name, target, _line in entry_points(setup_py, group)]
    return [(n, t) for n, t in found if n and _ENTRY.match(t)]
