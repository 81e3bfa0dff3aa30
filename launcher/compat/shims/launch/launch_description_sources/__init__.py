"""launch.launch_description_sources (launcher.api.sources)."""

from launcher.api.sources import (
    AnyLaunchDescriptionSource,
    FrontendLaunchDescriptionSource,
    InvalidPythonLaunchFileError,
    PythonLaunchDescriptionSource,
    XMLLaunchDescriptionSource,
    YAMLLaunchDescriptionSource,
    get_launch_description_from_any_launch_file,
    get_launch_description_from_frontend_launch_file,
    get_launch_description_from_python_launch_file,
    load_python_launch_file_as_module,
)

__all__ = ["AnyLaunchDescriptionSource", "FrontendLaunchDescriptionSource",
           "InvalidPythonLaunchFileError", "PythonLaunchDescriptionSource",
           "XMLLaunchDescriptionSource", "YAMLLaunchDescriptionSource",
           "get_launch_description_from_any_launch_file",
           "get_launch_description_from_frontend_launch_file",
           "get_launch_description_from_python_launch_file",
           "load_python_launch_file_as_module"]


from launcher.compat.finder import rest_from_layout  # noqa: E402

__getattr__ = rest_from_layout(__name__)
