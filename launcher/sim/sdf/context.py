"""What loading one SDF document shares: its version, URIs, includes and warnings.

`<include>` and mesh URIs resolve like Gazebo's (`model://` on the resource path,
`package://` through the package index, relative to the including file, absolute,
`file://`); an include that leads back to a file being included is a cycle. Warnings are
collected once each, with file:line, for the sim to log.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from launcher.errors import LaunchError
from launcher.sim.resources import SDF_VERSIONS, ResourceNotFound, model_file, resolve_uri
from launcher.sim.sdf.xmltree import Element, SdfError, parse
from launcher.user_files import read_text

OLDEST, NEWEST = SDF_VERSIONS



class AssetNotFound(SdfError, ResourceNotFound):
    """A mesh, model or file an SDF names that is nowhere (at the element naming it)."""

@dataclass(frozen=True)
class Origin:
    """Where a model element came from: its file (None for a string) and SDF version."""

    path: Path | None
    version: tuple[int, int]

    @property
    def base(self) -> Path | None:
        return self.path.parent if self.path is not None else None


@dataclass
class Context:
    environ: Mapping[str, str] | None = None
    packages: Any = None
    warnings: list[str] = field(default_factory=list)
    _stack: list[Path] = field(default_factory=list)

    def warn(self, element: Element, message: str) -> None:
        text = f"{element.location.file}:{element.location.line}: {message}"
        if text not in self.warnings:
            self.warnings.append(text)

    def resolve(self, uri: str, element: Element, origin: Origin, what: str) -> Path:
        try:
            return resolve_uri(uri, origin.base, self.packages, self.environ)
        except ResourceNotFound as exc:
            raise AssetNotFound(f"{what} {exc.message}", element.location) from None
        except LaunchError as exc:
            raise element.error(f"{what} {exc.message}") from None

    @contextmanager
    def inside(self, origin: Origin) -> Iterator[None]:
        """While a file's models are built: includes leading back to it are cycles."""
        if origin.path is not None:
            self._stack.append(origin.path)
        try:
            yield
        finally:
            if origin.path is not None:
                self._stack.pop()

    def include(self, element: Element, origin: Origin,
                kinds: tuple[str, ...] = ("model",)) -> tuple[Element, Origin]:
        """The `<model>` (or another of `kinds`: a world may include a `<light>`) an
        `<include>` names, and where it came from."""
        uri = element.value("uri")
        if not uri:
            raise element.error("<include> needs a <uri>")
        path = self.resolve(uri, element, origin, "<include>")
        if path.is_dir():
            path = self._model_file(path, element)
        if path in self._stack:
            chain = " -> ".join(str(p) for p in [*self._stack[self._stack.index(path):], path])
            raise element.error(f"<include> of '{uri}' makes a cycle: {chain}")
        root, version = read(read_text(path), str(path))
        found = next((root.find(kind) for kind in kinds if root.find(kind) is not None), None)
        if found is None:
            raise root.error(f"'{uri}' ({path}) holds no {' or '.join(f'<{k}>' for k in kinds)}"
                             " to include")
        return found, Origin(path, version)

    def _model_file(self, folder: Path, element: Element) -> Path:
        try:
            return model_file(folder)
        except LaunchError as exc:
            raise element.error(exc.message) from None



def opened(text: str, path: Path | None, tag: str, hint: str,
           environ: Mapping[str, str] | None, packages: Any) -> tuple[Element, Origin, Context]:
    """The document's `<world>` or `<model>` (top_element), where it came from, and the
    context it is read in."""
    element, origin = top_element(text, path, tag, hint)
    return element, origin, Context(environ, packages)


def top_element(text: str, path: Path | None, tag: str,
                hint: str) -> tuple[Element, Origin]:
    """The document's `<world>` or `<model>` (`tag`) and where it came from; its absence is
    an error with `hint` saying what the file is for instead."""
    root, version = read(text, str(path) if path else "<string>")
    element = root.find(tag)
    if element is None:
        raise root.error(f"no <{tag}> in this SDF file{hint}")
    return element, Origin(path, version)


def read(text: str, label: str) -> tuple[Element, tuple[int, int]]:
    """The `<sdf>` root of a document and its version, checked."""
    root = parse(text, label)
    if root.tag != "sdf":
        raise root.error(f"expected an <sdf> document, found <{root.tag}>")
    raw = root.get("version")
    if raw is None:
        raise root.error(f"<sdf> has no version attribute (launcher reads SDF "
                         f"{_text(OLDEST)} to {_text(NEWEST)})")
    version = parse_version(raw)
    if version is None or not OLDEST <= version <= NEWEST:
        raise root.error(f"unsupported SDF version '{raw}': launcher reads SDF {_text(OLDEST)} "
                         f"to {_text(NEWEST)}")
    return root, version


def parse_version(raw: str) -> tuple[int, int] | None:
    major, _, minor = raw.strip().partition(".")
    if not (major.isdigit() and minor.isdigit()):
        return None
    return int(major), int(minor)


def _text(version: tuple[int, int]) -> str:
    return f"{version[0]}.{version[1]}"


__all__ = ["Context", "Origin", "SdfError", "read"]
