"""launch_xml: XML launch files, read by launcher's XML frontend (launcher.frontend.xml_loader)."""

from launch_xml import launch_description_sources
from launch_xml.entity import Entity
from launch_xml.parser import Parser

__all__ = ["Entity", "Parser", "launch_description_sources"]
