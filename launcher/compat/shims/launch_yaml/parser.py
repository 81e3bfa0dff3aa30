"""launch_yaml.Parser: YAML launch files into entities (launcher's YAML loader)."""

from __future__ import annotations

from typing import Any

from launch import frontend

from launch_yaml.entity import Entity
from launcher.frontend.yaml_loader import load_yaml

__all__ = ["Entity", "Parser"]


class Parser(frontend.Parser):
    """The YAML frontend."""

    @classmethod
    def load(cls, file: Any) -> tuple[Entity, Parser]:
        """The root entity of a YAML launch file (a path or an open file)."""
        if hasattr(file, "read"):
            text, name = file.read(), str(getattr(file, "name", "<yaml>"))
        else:
            with open(file, encoding="utf-8") as stream:
                text, name = stream.read(), str(file)
        text = text.decode() if isinstance(text, bytes) else text
        return Entity(load_yaml(text, name)), cls()

    @classmethod
    def get_file_extensions(cls) -> set[str]:
        return {"launch.yaml", "launch.yml", "yaml", "yml", "launch"}
