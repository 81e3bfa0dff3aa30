"""launch.launch_description_sources (launcher.api)."""

from launcher.api import (  # noqa: F401
    AnyLaunchDescriptionSource,
    LaunchDescriptionSource,
    PythonLaunchDescriptionSource,
    XMLLaunchDescriptionSource,
    YAMLLaunchDescriptionSource,
)

FrontendLaunchDescriptionSource = LaunchDescriptionSource
