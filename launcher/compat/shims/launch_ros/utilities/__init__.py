"""launch_ros.utilities (launcher.api.ros)."""

from launcher.api.ros import (
    add_node_name,
    evaluate_parameters,
    get_node_name_count,
    is_namespace_absolute,
    is_root_namespace,
    make_namespace_absolute,
    normalize_parameters,
    normalize_remap_rule,
    normalize_remap_rules,
    prefix_namespace,
    to_parameters_list,
)

__all__ = ["add_node_name", "evaluate_parameters", "get_node_name_count",
           "is_namespace_absolute", "is_root_namespace", "make_namespace_absolute",
           "normalize_parameters", "normalize_remap_rule", "normalize_remap_rules",
           "prefix_namespace", "to_parameters_list"]


from launcher.compat.finder import rest_from_layout  # noqa: E402

__getattr__ = rest_from_layout(__name__)
