"""launch_yaml's YAMLLaunchDescriptionSource: a YAML launch file to include (launch's own)."""

from launch.launch_description_sources import YAMLLaunchDescriptionSource

from launch_yaml.parser import Parser

__all__ = ["Parser", "YAMLLaunchDescriptionSource"]
