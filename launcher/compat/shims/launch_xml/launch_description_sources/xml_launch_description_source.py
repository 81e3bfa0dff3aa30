"""launch_xml's XMLLaunchDescriptionSource: an XML launch file to include (launch's own)."""

from launch.launch_description_sources import XMLLaunchDescriptionSource

from launch_xml.parser import Parser

__all__ = ["Parser", "XMLLaunchDescriptionSource"]
