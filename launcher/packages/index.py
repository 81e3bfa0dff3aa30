"""Finding packages: workspaces, the checkout's `packages/`, built-ins, then ament prefixes.

Search order (the first package of a name wins; a second one is a warning naming both):
  1. every root in LAUNCHER_PACKAGE_PATH, then in ROS_PACKAGE_PATH (ROS 1's, as rospack
     crawls it), colon-separated, scanned recursively like colcon: a folder with a package.xml
     is a package; folders holding COLCON_IGNORE or AMENT_IGNORE, hidden folders and Python
     caches are skipped;
  2. `packages/` of the launcher checkout the command runs in (found from the working folder);
  3. the packages built into launcher (`launcher/builtin/`);
  4. the install prefixes in AMENT_PREFIX_PATH, through the ament resource index, so a real
     ROS install's share folders work too.
A compiled package (ament_cmake, cmake, catkin) found only as source, as when a whole repository
is cloned into a workspace's src/ and never built, has no executables; where launcher has a
built-in package of that name, the built-in is its stand-in: its executables and components
run, the source stays the package's share folder, and the index says so once (a notice).
Packages are used in place: `$(find-pkg-share pkg)` is the package folder. For
`$(find-pkg-prefix pkg)` launcher keeps a folder of links per workspace root
(`<cache>/prefixes/<hash>/share/<pkg>` -> the package), so `<prefix>/share/<pkg>/…` works.
"""

from __future__ import annotations

import os
import zlib
from collections.abc import Iterator, Mapping
from pathlib import Path

from launcher.errors import LaunchError, did_you_mean
from launcher.packages.manifest import Package, read_manifest
from launcher.records import dataclass, field

BUILTIN_ROOT = Path(__file__).resolve().parent.parent / "builtin"
IGNORE_MARKERS = ("COLCON_IGNORE", "AMENT_IGNORE")
_SKIP = {"__pycache__", "node_modules", "build", "install", "log"}


class PackageNotFound(LaunchError):
    pass


def cache_root(environ: Mapping[str, str]) -> Path:
    if environ.get("LAUNCHER_CACHE_DIR"):
        return Path(environ["LAUNCHER_CACHE_DIR"]).expanduser()
    base = environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "launcher"


def find_checkout(start: Path) -> Path | None:
    """The launcher checkout that `start` is in: a folder with pyproject.toml and packages/."""
    for folder in (start, *start.parents):
        if (folder / "packages").is_dir() and (folder / "launcher" / "packages").is_dir() \
                and (folder / "pyproject.toml").is_file():
            return folder
    return None


@dataclass
class SearchRoot:
    path: Path
    origin: str  # workspace | checkout | builtin | ament


@dataclass
class PackageIndex:
    roots: list[SearchRoot]
    cache: Path
    packages: dict[str, Package] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    notices: list[str] = field(default_factory=list)  # worth one line, not a warning

    @classmethod
    def from_environment(cls, environ: Mapping[str, str] | None = None,
                         cwd: Path | None = None) -> PackageIndex:
        env = os.environ if environ is None else environ
        roots = [SearchRoot(Path(p).expanduser(), "workspace")
                 for variable in ("LAUNCHER_PACKAGE_PATH", "ROS_PACKAGE_PATH")
                 for p in env.get(variable, "").split(os.pathsep) if p]
        checkout = find_checkout((cwd or Path.cwd()).resolve())
        if checkout is not None:
            roots.append(SearchRoot(checkout / "packages", "checkout"))
        roots.append(SearchRoot(BUILTIN_ROOT, "builtin"))
        roots += [SearchRoot(Path(p), "ament")
                  for p in env.get("AMENT_PREFIX_PATH", "").split(os.pathsep) if p]
        index = cls(roots, cache_root(env))
        index.build()
        return index

    # --- building ---------------------------------------------------------------------------
    def build(self) -> None:
        """Scan every root (again: edits are seen on every build)."""
        self.packages, self.warnings, self.notices = {}, [], []
        for root in self.roots:
            if root.origin == "ament":
                found = _ament_packages(root.path)
            else:
                found = _scan(str(root.path), root.origin)
                link_prefix = self._link_prefix(root.path)
                for package in found:
                    package.prefix = link_prefix
            for package in found:
                self._add(package)

    def _add(self, package: Package) -> None:
        first = self.packages.get(package.name)
        if first is None:
            self.packages[package.name] = package
        elif first.path.resolve() == package.path.resolve():
            return
        elif stands_in(package, first):
            first.stand_in = package
            self.notices.append(f"package '{first.name}' at {first.path} is source only (a "
                                f"compiled {first.build_type} package, never built): "
                                "launcher runs its own implementation of it")
        else:
            self.warnings.append(f"package '{package.name}' is found twice: {first.path} "
                                 f"(used) and {package.path} (ignored)")

    def _link_prefix(self, root: Path) -> Path:
        resolved = root.resolve()
        digest = f"{zlib.crc32(str(resolved).encode()):08x}"
        return self.cache / "prefixes" / f"{resolved.name}-{digest}"

    # --- looking up -------------------------------------------------------------------------
    def __iter__(self) -> Iterator[Package]:
        return iter(self.packages.values())

    def __contains__(self, name: str) -> bool:
        return name in self.packages

    def get(self, name: str) -> Package:
        package = self.packages.get(name)
        if package is None:
            searched = "\n".join(f"  {r.path} ({r.origin})" for r in self.roots)
            hint = ""
            if not any(r.origin in ("workspace", "checkout") for r in self.roots):
                hint = ("\nto add your workspace: LAUNCHER_PACKAGE_PATH=/path/to/ws/src (a "
                        "folder of packages; several with ':'), or source a colcon install's "
                        "setup.sh (AMENT_PREFIX_PATH); `. hooks/setup.sh` of launcher's "
                        "checkout puts launcher and its hooks in your shell")
            raise PackageNotFound(f"package '{name}' not found"
                                  f"{did_you_mean(name, self.packages)}; searched:\n{searched}"
                                  f"{hint}")
        return package

    def share(self, name: str) -> Path:
        return self.get(name).path

    def prefix(self, name: str) -> Path:
        """An install prefix whose share/<name> is the package (made of links if needed)."""
        package = self.get(name)
        assert package.prefix is not None
        if package.origin != "ament":
            link = package.prefix / "share" / name
            if not link.is_symlink() or Path(os.readlink(link)) != package.path:
                link.parent.mkdir(parents=True, exist_ok=True)
                if link.is_symlink() or link.exists():
                    link.unlink()
                link.symlink_to(package.path, target_is_directory=True)
        return package.prefix


def stands_in(builtin: Package, source: Package) -> bool:
    """Whether launcher's `builtin` package runs in place of the compiled `source` package:
    only a built-in with something to run (a message package's source is read as it is)."""
    return builtin.origin == "builtin" and source.origin in ("workspace", "checkout") and \
        source.compiled and any(tag in builtin.exports for tag in ("executable", "component"))


def _scan(root: str, origin: str) -> list[Package]:
    """Packages below `root` (plain strings while walking: pathlib costs here)."""
    found: list[Package] = []
    try:
        entries = list(os.scandir(root))
    except OSError:
        return found
    names = {e.name for e in entries}
    if any(marker in names for marker in IGNORE_MARKERS):
        return found
    if "package.xml" in names:
        return [read_manifest(Path(root, "package.xml"), origin)]
    for entry in sorted(entries, key=lambda e: e.name):
        if entry.name.startswith(".") or entry.name in _SKIP:
            continue
        if entry.is_dir(follow_symlinks=True):
            found += _scan(entry.path, origin)
    return found


def _ament_packages(prefix: Path) -> list[Package]:
    marker = prefix / "share" / "ament_index" / "resource_index" / "packages"
    try:
        names = sorted(os.listdir(marker))
    except OSError:
        return []
    found = []
    for name in names:
        share = prefix / "share" / name
        manifest = share / "package.xml"
        try:
            package = read_manifest(manifest, "ament") if manifest.exists() else \
                Package(name=name, path=share, origin="ament")
        except LaunchError:
            package = Package(name=name, path=share, origin="ament")
        package.prefix = prefix
        found.append(package)
    return found
