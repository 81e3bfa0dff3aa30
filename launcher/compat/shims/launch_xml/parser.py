"""launch_xml.Parser: XML launch files into entities (launcher's XML loader)."""

from __future__ import annotations

from typing import Any

from launch import frontend

from launch_xml.entity import Entity
from launcher.frontend.xml_loader import load_xml

__all__ = ["Entity", "Parser"]


class Parser(frontend.Parser):
    """The XML frontend."""

    @classmethod
    def load(cls, file: Any) -> tuple[Entity, Parser]:
        """The root entity of an XML launch file (a path or an open file)."""
        data, name = _read(file)
        return Entity(load_xml(data, name)), cls()

    @classmethod
    def get_file_extensions(cls) -> set[str]:
        return {"launch.xml", "xml", "launch"}


def _read(file: Any) -> tuple[bytes, str]:
    if hasattr(file, "read"):
        data = file.read()
        name = str(getattr(file, "name", "<xml>"))
    else:
        with open(file, "rb") as stream:
            data, name = stream.read(), str(file)
    return (data.encode() if isinstance(data, str) else data), name
