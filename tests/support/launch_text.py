"""Launch descriptions parsed from inline launch text, and substitution text performed."""

from __future__ import annotations

import textwrap
from pathlib import Path

from launcher.description.action import LaunchDescription
from launcher.description.registry import default_registry
from launcher.description.substitution import perform_text
from launcher.errors import Location
from launcher.frontend.builder import build_description, parse_substitutions
from launcher.frontend.entity import Attribute
from launcher.frontend.xml_loader import load_xml
from launcher.frontend.yaml_loader import load_yaml
from launcher.runtime.context import LaunchContext


def yaml_description(text: str, file: str = "test.launch.yaml") -> LaunchDescription:
    return build_description(load_yaml(textwrap.dedent(text).lstrip("\n"), file), Path(file))


def xml_description(text: str, file: str = "test.launch.xml") -> LaunchDescription:
    return build_description(load_xml(textwrap.dedent(text).strip().encode(), file), Path(file))


def evaluate(text: str, context: LaunchContext | None = None, roslaunch: bool = False) -> str:
    """Perform substitution text as a launch file would (a roslaunch file: `roslaunch`)."""
    context = context or LaunchContext({}, {})
    attribute = Attribute(text, Location("inline", 1, 1), 0, roslaunch=roslaunch)
    return perform_text(context, parse_substitutions(attribute, default_registry()))
