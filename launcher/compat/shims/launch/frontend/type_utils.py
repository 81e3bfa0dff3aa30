"""launch.frontend.type_utils: the types frontends' `get_attr` takes, by their names in files."""

from __future__ import annotations

from typing import Any, List  # noqa: UP035 (launch's types are typing.List[...])

from launch.frontend.entity import Entity
from launch.utilities.type_utils import is_typing_list

__all__ = ["Entity", "check_is_list_entity", "get_data_type_from_identifier", "is_typing_list"]

# `type=` as launch files write it (a parameter's, an argument's)
_IDENTIFIERS: dict[str, Any] = {
    "str": str, "bool": bool, "float": float, "int": int,
    "list_of_str": List[str], "list_of_bool": List[bool],  # noqa: UP006
    "list_of_float": List[float], "list_of_int": List[int],  # noqa: UP006
    "yaml": None,
}


def check_is_list_entity(data_type: Any) -> bool:
    """Whether `data_type` is `List[Entity]` (of an Entity class)."""
    if not is_typing_list(data_type) or not getattr(data_type, "__args__", None):
        return False
    item = data_type.__args__[0]
    return isinstance(item, type) and issubclass(item, Entity)


def get_data_type_from_identifier(type_identifier: str) -> Any:
    """The type a `type=` word names (`list_of_int` → List[int]; `yaml` → None)."""
    if type_identifier not in _IDENTIFIERS:
        raise ValueError(f"Got invalid type identifier '{type_identifier}'")
    return _IDENTIFIERS[type_identifier]
