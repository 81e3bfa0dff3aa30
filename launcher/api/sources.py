"""launch's launch description sources: where IncludeLaunchDescription takes a description
from (a file of any of the formats, by its path, or a description made in Python)."""

from __future__ import annotations

from typing import Any


class LaunchDescriptionSource:
    """A description given as it is (`launch_description`), or found at `location`."""

    def __init__(self, launch_description: Any = None, location: Any = "<string>",
                 method: str = "unspecified mechanism from a script") -> None:
        self.launch_description, self.location, self.method = launch_description, location, method

    def try_get_launch_description_without_context(self) -> Any:
        return self.launch_description

    def get_launch_description(self, context: Any) -> Any:
        """The description: the one given, or the file's, read now."""
        if self.launch_description is None:
            from launcher.description.substitution import perform_text, to_text

            path = perform_text(context, to_text(self.location))
            self.launch_description = context.load_description(_path(path))
        return self.launch_description


def _path(text: str) -> Any:
    from pathlib import Path

    return Path(text)


class AnyLaunchDescriptionSource(LaunchDescriptionSource):
    """A launch file of any format (.py, .xml, .yaml, .launch)."""

    def __init__(self, launch_file_path: Any) -> None:
        super().__init__(None, launch_file_path, "interpreted launch file")


class PythonLaunchDescriptionSource(LaunchDescriptionSource):
    def __init__(self, launch_file_path: Any) -> None:
        super().__init__(None, launch_file_path, "interpreted python launch file")


class FrontendLaunchDescriptionSource(LaunchDescriptionSource):
    def __init__(self, launch_file_path: Any, *, method: str = "interpreted frontend launch "
                 "file", parser: Any = None) -> None:
        super().__init__(None, launch_file_path, method)


class XMLLaunchDescriptionSource(FrontendLaunchDescriptionSource):
    def __init__(self, launch_file_path: Any) -> None:
        super().__init__(launch_file_path, method="interpreted XML launch file")


class YAMLLaunchDescriptionSource(FrontendLaunchDescriptionSource):
    def __init__(self, launch_file_path: Any) -> None:
        super().__init__(launch_file_path, method="interpreted YAML launch file")


class InvalidLaunchFileError(Exception):
    """A launch file that cannot be read (launch's)."""

    def __init__(self, extension: str = "", *, likely_errors: Any = None) -> None:
        self._extension, self._likely_errors = extension, likely_errors
        super().__init__(f"Caught exception when trying to load file of format "
                         f"[{extension}]" if extension else "Invalid launch file")


class InvalidPythonLaunchFileError(Exception):
    """A Python launch file without generate_launch_description()."""


def get_launch_description_from_any_launch_file(launch_file_path: Any, *,
                                                parser: Any = None) -> Any:
    """The description in a launch file of any format, read as `launcher launch` reads it."""
    from launcher.frontend.loader import load_file

    return load_file(_path(str(launch_file_path)))


def get_launch_description_from_python_launch_file(python_launch_file_path: Any) -> Any:
    return get_launch_description_from_any_launch_file(python_launch_file_path)


def get_launch_description_from_frontend_launch_file(frontend_launch_file_path: Any, *,
                                                     parser: Any = None) -> Any:
    return get_launch_description_from_any_launch_file(frontend_launch_file_path)


def load_python_launch_file_as_module(python_launch_file_path: Any) -> Any:
    """The Python launch file, run as a module (its failures said at its line)."""
    from launcher.frontend.python_loader import load_module

    return load_module(_path(str(python_launch_file_path)), "launch_file_module")
