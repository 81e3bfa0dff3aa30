"""Files and paths: `$(dirname)`, `$(filename)`, `$(file-content)`, `$(find-exec)`,
`$(log_dir)`, and the Python API's PathJoinSubstitution."""

from __future__ import annotations

import os
from pathlib import Path

from launcher.description.substitution import (
    Substitution,
    Text_,
    perform_text,
    substitution,
    to_text,
)
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext
from launcher.user_files import read_text


def _current_file(sub: Substitution, context: LaunchContext) -> Path:
    if context.files.current is None:
        raise sub.fail(f"{sub.names[0]} is only known inside a launch file")
    return context.files.current


@substitution("dirname")
@dataclass(frozen=True)
class ThisLaunchFileDir(Substitution):
    """The folder of the launch file being read."""

    def perform(self, context: LaunchContext) -> str:
        return str(_current_file(self, context).parent)


@substitution("filename")
@dataclass(frozen=True)
class ThisLaunchFile(Substitution):
    """The path of the launch file being read."""

    def perform(self, context: LaunchContext) -> str:
        return str(_current_file(self, context))


@substitution("file-content")
@dataclass(frozen=True)
class FileContent(Substitution):
    """The text of a file (relative paths are taken from the launch file's folder)."""

    path: Text_

    def perform(self, context: LaunchContext) -> str:
        raw = perform_text(context, self.path)
        path = Path(raw)
        if not path.is_absolute() and context.files.current is not None:
            path = context.files.current.parent / path
        try:
            return read_text(path)
        except FileNotFoundError:
            raise self.fail(f"file-content: no file '{path}'") from None
        except (OSError, UnicodeDecodeError) as exc:
            raise self.fail(f"file-content: cannot read '{path}': {exc}") from None


@substitution("find-exec")
@dataclass(frozen=True)
class FindExecutable(Substitution):
    """The full path of an executable on the launch's PATH."""

    name: Text_

    def perform(self, context: LaunchContext) -> str:
        name = perform_text(context, self.name)
        import shutil

        found = shutil.which(name, path=context.environment.get("PATH", os.defpath))
        if found is None:
            raise self.fail(f"find-exec: no executable '{name}' on PATH")
        return found


@substitution("log_dir")
@dataclass(frozen=True)
class LogDir(Substitution):
    """The log folder of this run."""

    def perform(self, context: LaunchContext) -> str:
        if context.log_dir is None:
            raise self.fail("log_dir: this run has no log folder")
        return str(context.log_dir)


@dataclass(frozen=True, init=False)
class PathJoinSubstitution(Substitution):
    """Python API: join path parts (each text or substitutions) with '/'."""

    parts: tuple[Text_, ...] = ()

    def __init__(self, parts: list) -> None:
        object.__setattr__(self, "parts", tuple(to_text(p) for p in parts))
        object.__setattr__(self, "where", None)

    def perform(self, context: LaunchContext) -> str:
        return os.path.join(*(perform_text(context, p) for p in self.parts))

    def __truediv__(self, other: object) -> PathJoinSubstitution:
        return PathJoinSubstitution([*self.parts, to_text(other)])

    def describe(self) -> str:
        return "/".join(str(p) for p in self.parts)
