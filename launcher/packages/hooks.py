"""Apply every package's environment hooks, as sourcing a colcon workspace would.

A package's hooks are the files in its `hooks/` folder: `NAME.dsv`, `NAME.sh`, `NAME.bash`
and their `.in` templates. For each NAME, a `.dsv` wins over a shell hook (as in colcon).
Order: underlays first (ament prefixes are taken as already sourced and skipped, then the
built-in packages, the checkout, LAUNCHER_PACKAGE_PATH), and packages in dependency order
within each. Hooks of packages used in place see `@CMAKE_INSTALL_PREFIX@` as the package's
link prefix, whose `share/<pkg>` is the package folder; paths through it are written as the
package's real folder.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from pathlib import Path

from launcher.errors import Location, ParseError
from launcher.packages.dsv import HookEnvironment, apply_dsv
from launcher.packages.index import PackageIndex
from launcher.packages.manifest import Package
from launcher.packages.shell_hooks import run_shell_hook
from launcher.packages.templates import configure, template_variables
from launcher.records import dataclass
from launcher.user_files import read_text

TIERS = ("builtin", "checkout", "workspace")
SHELLS = {".sh": "sh", ".bash": "bash"}


@dataclass(frozen=True)
class Hook:
    package: Package
    path: Path  # the file as written (maybe a .in template)


def package_hooks(package: Package) -> list[Hook]:
    folder = package.path / "hooks"
    try:
        # (not only regular files: a FIFO named as a hook is refused when read, not skipped)
        files = sorted(p for p in folder.iterdir() if p.exists() and not p.is_dir())
    except OSError:
        return []
    by_stem: dict[str, dict[str, Path]] = {}
    for path in files:
        base = path.name.removesuffix(".in")
        stem, kind = os.path.splitext(base)
        if kind in (".dsv", *SHELLS):
            by_stem.setdefault(stem, {}).setdefault(kind, path)
    chosen = []
    for kinds in by_stem.values():
        for kind in (".dsv", ".sh", ".bash"):
            if kind in kinds:
                chosen.append(Hook(package, kinds[kind]))
                break
    return chosen


def ordered(index: PackageIndex) -> list[Package]:
    """Packages whose hooks apply, underlays first, dependencies before dependents."""
    result: list[Package] = []
    for tier in TIERS:
        members = {p.name: p for p in index if p.origin == tier}
        done: set[str] = set()

        def visit(package: Package, trail: tuple[str, ...], members=members, done=done) -> None:
            if package.name in done or package.name in trail:
                return
            for dep in sorted(package.run_dependencies()):
                if dep in members:
                    visit(members[dep], (*trail, package.name))
            done.add(package.name)
            result.append(package)

        for name in sorted(members):
            visit(members[name], ())
    return result


class HookRunner:
    def __init__(self, index: PackageIndex, environment: Mapping[str, str]) -> None:
        self.index = index
        self.env = HookEnvironment(dict(environment))
        self.applied: list[Path] = []
        self._active: list[Path] = []

    def run(self) -> dict[str, str]:
        for package in ordered(self.index):
            hooks = package_hooks(package)
            if not hooks:
                continue
            prefix = self.index.prefix(package.name)
            link = str(prefix / "share" / package.name)
            self.env.real = lambda value, link=link, real=str(package.path): \
                value.replace(link, real, 1) if value.startswith(link) else value
            for hook in hooks:
                self.apply(package, prefix, hook.path, None)
        return self.env.finish()

    def apply(self, package: Package, prefix: Path, path: Path, where: Location | None) -> None:
        if not path.exists():
            raise ParseError(f"hook '{path}' does not exist", where)
        if path in self._active:
            chain = " -> ".join(str(p) for p in [*self._active, path])
            raise ParseError(f"hook cycle through 'source': {chain}", where)
        self._active.append(path)
        try:
            self._apply(package, prefix, path)
        finally:
            self._active.pop()

    def _apply(self, package: Package, prefix: Path, path: Path) -> None:
        text = read_text(path)
        templated = path.name.endswith(".in")
        if templated:
            text = configure(text, template_variables(package, prefix), path)
        kind = os.path.splitext(path.name.removesuffix(".in"))[1]
        if kind == ".dsv":
            apply_dsv(path, text, prefix, self.env,
                      lambda target, where: self._source(package, prefix, target, where))
        else:  # a shell sources a file: write the configured text out first
            configured = self._write_configured(package, path, text) if templated else path
            self._shell(path, configured, prefix, SHELLS.get(kind, "sh"))
        self.applied.append(path)

    def _source(self, package: Package, prefix: Path, target: Path, where: Location) -> None:
        twin = target.with_suffix(".dsv")
        if target.suffix in SHELLS and twin.exists():
            target = twin
        package_target = _through_links(target, package, prefix)
        self.apply(package, prefix, package_target, where)

    def _shell(self, path: Path, configured: Path, prefix: Path, shell: str) -> None:
        before = self.env.values
        after = run_shell_hook(path, configured, prefix, before, shell)
        for name in set(before) | set(after):
            if before.get(name) != after.get(name):
                self.env.note(name)
                if name in after:
                    after[name] = os.pathsep.join(self.env.real(v)
                                                  for v in after[name].split(os.pathsep))
        self.env.values = after

    def _write_configured(self, package: Package, path: Path, text: str) -> Path:
        folder = self.index.cache / "hooks" / package.name
        folder.mkdir(parents=True, exist_ok=True)
        target = folder / path.name.removesuffix(".in")
        target.write_text(text, encoding="utf-8")
        return target


def _through_links(path: Path, package: Package, prefix: Path) -> Path:
    link = prefix / "share" / package.name
    try:
        return package.path / path.relative_to(link)
    except ValueError:
        return path


def apply_hooks(index: PackageIndex, environment: Mapping[str, str]) -> dict[str, str]:
    """The environment with every package's hooks applied."""
    return HookRunner(index, environment).run()


