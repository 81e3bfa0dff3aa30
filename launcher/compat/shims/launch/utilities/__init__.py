"""launch.utilities (launcher.api.utilities)."""

from launcher.api.utilities import (
    ensure_argument_type,
    is_a,
    is_a_subclass,
    isclassinstance,
    normalize_to_list_of_entities,
    normalize_to_list_of_substitutions,
    perform_substitutions,
    visit_all_entities_and_collect_futures,
)

__all__ = ["ensure_argument_type", "is_a", "is_a_subclass", "isclassinstance",
           "normalize_to_list_of_entities", "normalize_to_list_of_substitutions",
           "perform_substitutions", "visit_all_entities_and_collect_futures"]


from launcher.compat.finder import rest_from_layout  # noqa: E402

__getattr__ = rest_from_layout(__name__)
