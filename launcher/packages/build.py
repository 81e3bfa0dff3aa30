"""Building a workspace as ROS users build it: the real colcon (colcon-core with its ROS, CMake
and Python extensions) and a real CMake, from launcher's build tools, which the set-up
installs apart under `.venv/tools` so that they never shadow a colcon or cmake of the user's.

CMake runs with launcher's toolchain (ament_cmake/toolchain.cmake): no compiler is looked
for, `find_package(ament_cmake)` is answered by launcher's own ament_cmake modules, and a
package that needs a compiler or a ROS C++ library stops with a message that names it. Before
colcon starts, every package.xml below the base paths is read as launcher reads it, so a
malformed one is said with its file:line; after a failed build, the CMake errors in colcon's
logs are said with the CMakeLists.txt line they came from.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from collections.abc import Mapping
from pathlib import Path

from launcher.errors import LaunchError, Location, ParseError

AMENT_CMAKE = Path(__file__).with_name("ament_cmake")
TOOLS = Path(sys.prefix) / "tools"  # the build tools' prefix (pip install --prefix)
SKIPPED = {"build", "install", "log", "devel", ".git", "node_modules", "__pycache__"}


class BuildError(LaunchError):
    pass


def tools_site() -> Path:
    return TOOLS / "lib" / f"python{sys.version_info[0]}.{sys.version_info[1]}" / \
        "site-packages"


def check_installed() -> None:
    if not (tools_site() / "colcon_core").is_dir() or not (TOOLS / "bin" / "cmake").exists():
        raise BuildError(f"launcher's build tools (colcon, CMake) are not installed under "
                         f"{TOOLS}: sh hooks/bootstrap.sh test (or demo) installs them")


def environment(env: Mapping[str, str]) -> dict[str, str]:
    """colcon's environment: the tools first on PATH and PYTHONPATH (for colcon and the
    processes it starts, CMake and setup.py), launcher's CMake toolchain, Ninja."""
    result = dict(env)
    paths = [str(TOOLS / "bin"), *[p for p in env.get("PATH", "").split(os.pathsep) if p]]
    result["PATH"] = os.pathsep.join(paths)
    old = env.get("PYTHONPATH", "")
    result["PYTHONPATH"] = os.pathsep.join([str(tools_site()), *([old] if old else [])])
    result["CMAKE_TOOLCHAIN_FILE"] = str(AMENT_CMAKE / "toolchain.cmake")
    result.setdefault("CMAKE_GENERATOR", "Ninja")
    result["CMAKE_COMMAND"] = str(TOOLS / "bin" / "cmake")
    result["COLCON_PYTHON_EXECUTABLE"] = sys.executable
    return result


def check_manifests(bases: list[Path]) -> None:
    """Read every package.xml below `bases` (not below a COLCON_IGNORE or a build output), as
    launcher reads them: a malformed one is a ParseError with its file:line."""
    from launcher.packages.manifest import read_manifest

    for base in bases:
        for folder, subfolders, files in os.walk(base):
            if "COLCON_IGNORE" in files or "CATKIN_IGNORE" in files:
                subfolders[:] = []
                continue
            subfolders[:] = sorted(s for s in subfolders if s not in SKIPPED
                                   and not s.startswith("."))
            if "package.xml" in files:
                read_manifest(Path(folder) / "package.xml")
                _check_as_colcon_reads(Path(folder) / "package.xml")
                subfolders[:] = []  # a package holds no packages


def _check_as_colcon_reads(path: Path) -> None:
    """catkin_pkg's checks, which colcon's ROS extension applies (a package that fails them
    would be built as a plain CMake or Python package, silently): said with the line of the
    value they name."""
    site = str(tools_site())
    added = site not in sys.path
    if added:
        sys.path.append(site)
    try:
        from catkin_pkg.package import InvalidPackage, parse_package
    except ImportError:
        return
    finally:
        if added:
            sys.path.remove(site)
    try:
        parse_package(str(path))
    except InvalidPackage as exc:
        lines = [line for line in str(exc).splitlines() if not line.startswith("Error(s) in")]
        text = path.read_text(encoding="utf-8", errors="replace")
        line = 0
        for quoted in re.findall(r'"([^"]+)"', lines[0] if lines else ""):
            where = text.find(quoted)
            if where >= 0:
                line = text.count("\n", 0, where) + 1
                break
        raise ParseError(f"package.xml as colcon reads it: {'; '.join(lines)}",
                         Location(str(path), line)) from None


def run_colcon(argv: list[str], cwd: Path, env: Mapping[str, str]) -> int:
    """colcon ARGV… in `cwd`; its output is the user's, and a failure's CMake errors are said
    again, located, through the reporter."""
    check_installed()
    code = "import sys; from colcon_core.command import main; sys.exit(main())"
    done = subprocess.run([sys.executable, "-c", code, *argv], cwd=cwd,
                          env=environment(env))
    if done.returncode != 0 and argv[:1] == ["build"]:
        errors = cmake_errors(cwd / "log" / "latest_build")
        if errors:
            raise BuildError("colcon build failed:\n" + "\n".join(errors))
    return done.returncode


_CMAKE_ERROR = re.compile(r"^CMake Error at (?P<file>[^:\n]+):(?P<line>\d+) \((?P<command>\w+)\):"
                          r"\n(?P<text>(?:  .*\n|\n)*?)(?:Call Stack \(most recent call "
                          r"first\):\n(?P<stack>(?:  .*\n)+))?(?=\n|\S|\Z)", re.M)


def cmake_errors(log: Path) -> list[str]:
    """`path/CMakeLists.txt:LINE: command(): what`, for each CMake error in colcon's logs of
    the packages that failed, located at the package's own file (not launcher's modules)."""
    found: list[str] = []
    if not log.is_dir():
        return found
    for stderr in sorted(log.glob("*/stderr.log")):
        text = stderr.read_text(encoding="utf-8", errors="replace")
        package = stderr.parent.name
        source = _source_folder(stderr.parent)
        for match in _CMAKE_ERROR.finditer(text):
            file, line, command = match["file"], int(match["line"]), match["command"]
            for frame in (match["stack"] or "").splitlines():  # the package's own call
                called = re.match(r"\s+(?P<file>[^:]+):(?P<line>\d+) \((?P<command>\w+)\)",
                                  frame)
                if called and not Path(called["file"]).is_absolute():
                    file, line, command = called["file"], int(called["line"]), \
                        called["command"]
                    break
            if not Path(file).is_absolute() and source is not None:
                file = str(source / file)
            words = " ".join(match["text"].split()).removeprefix("launcher: ")
            what = words if words.startswith(f"{command}(") else f"{command}(): {words}"
            found.append(f"{Location(file, line)}: {what} (package '{package}')")
    ours = [f for f in found if re.match(r"\S+: (find_package|add_executable|add_library|"
                                         r"ament_environment_hooks)\(\w", f)]
    return ours or found


def _source_folder(package_log: Path) -> Path | None:
    """The package's source folder, from colcon's command log of it."""
    command = package_log / "command.log"
    if not command.is_file():
        return None
    found = re.search(r"cmake (\S+) -D", command.read_text(errors="replace"))
    return Path(found.group(1)) if found else None


__all__ = ["BuildError", "ParseError", "check_manifests", "environment", "run_colcon"]
