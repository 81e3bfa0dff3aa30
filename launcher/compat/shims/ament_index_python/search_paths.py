"""ament_index_python.search_paths."""

from ament_index_python.constants import AMENT_PREFIX_PATH_ENV_VAR
from ament_index_python.resources import get_search_paths

__all__ = ["AMENT_PREFIX_PATH_ENV_VAR", "get_search_paths"]
