"""ament_index_python.constants."""

AMENT_PREFIX_PATH_ENV_VAR = "AMENT_PREFIX_PATH"
RESOURCE_INDEX_SUBFOLDER = "share/ament_index/resource_index"

__all__ = ["AMENT_PREFIX_PATH_ENV_VAR", "RESOURCE_INDEX_SUBFOLDER"]
