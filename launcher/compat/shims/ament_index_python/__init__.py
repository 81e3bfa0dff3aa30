"""ament_index_python, answered from launcher's package index."""

from ament_index_python.packages import (  # noqa: F401
    PackageNotFoundError,
    get_package_prefix,
    get_package_share_directory,
    get_package_share_path,
    get_packages_with_prefixes,
)
