"""launch.utilities.type_utils: the scalar and list types launch files' values may take, and
their coercion from text by YAML's rules (`'1'` → 1, `'true'` → True, `'[1, 2]'` → [1, 2]).

Typed substitutions are normalized when an action is made (values kept, substitutions as
lists) and performed, then coerced, when it runs.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Any, List, Union  # noqa: UP035 (launch's types are typing.List[...])

import yaml

from launch import LaunchContext, Substitution
from launch.utilities import (
    ensure_argument_type,
    normalize_to_list_of_substitutions,
    perform_substitutions,
)
from launcher.description.substitution import Substitution as _AnySubstitution

__all__ = [
    "AllowedTypesTuple", "LaunchContext", "ListTypesTuple", "ScalarTypesTuple", "Substitution",
    "coerce_list", "coerce_to_type", "ensure_argument_type", "extract_type", "get_typed_value",
    "is_instance_of", "is_instance_of_valid_type", "is_normalized_substitution",
    "is_substitution", "is_typing_list", "is_valid_scalar_type",
    "normalize_to_list_of_substitutions", "normalize_typed_substitution",
    "perform_substitutions", "perform_typed_substitution",
]

ScalarTypesTuple = (int, float, bool, str)
ListTypesTuple = (List[int], List[float], List[bool], List[str])  # noqa: UP006
AllowedTypesTuple = ScalarTypesTuple + ListTypesTuple

ScalarTypesType = type[Union[int, float, bool, str]]  # noqa: UP007
ListTypesType = type[Union[List[int], List[float], List[bool], List[str]]]  # noqa: UP006, UP007
AllowedTypesType = Union[ScalarTypesType, ListTypesType]  # noqa: UP007
ScalarValueType = Union[int, float, bool, str]  # noqa: UP007
AllowedValueType = Any  # a scalar, or a uniform list of scalars
StrSomeValueType = Any  # such a value, strings standing for substitutions
NormalizedValueType = Any  # such a value, substitutions as lists of Substitution


def is_typing_list(data_type: Any) -> bool:
    """Whether `data_type` is `List` or `List[x]` (`list[x]` too)."""
    return data_type is list or getattr(data_type, "__origin__", None) in (list, list) and \
        hasattr(data_type, "__args__")


def is_valid_scalar_type(data_type: Any) -> bool:
    return data_type in ScalarTypesTuple


def extract_type(data_type: Any) -> tuple[type, bool]:
    """`(scalar type, is a list)`: `List[int]` → (int, True), `bool` → (bool, False)."""
    is_list = is_typing_list(data_type) and bool(getattr(data_type, "__args__", None))
    scalar = data_type.__args__[0] if is_list else data_type
    if not is_valid_scalar_type(scalar):
        raise ValueError(f"Unrecognized data type: {data_type}")
    return scalar, is_list


def is_instance_of_valid_type(value: Any, *, can_be_str: bool = False) -> bool:
    """Whether `value` is a scalar, or a uniform list of one scalar type (strings mixed in
    with `can_be_str`: they stand for substitutions)."""
    if not isinstance(value, list):
        return isinstance(value, ScalarTypesTuple)
    kind = next((type(x) for x in value if type(x) is not str), str)
    if kind not in ScalarTypesTuple:
        return False
    allowed = (kind, str) if can_be_str else kind
    return all(isinstance(x, allowed) for x in value)


def is_instance_of(value: Any, data_type: Any = None, *, can_be_str: bool = False) -> bool:
    """Whether `value` is of `data_type` (None: of any allowed type)."""
    if data_type is None:
        return is_instance_of_valid_type(value, can_be_str=can_be_str)
    scalar, is_list = extract_type(data_type)
    allowed = (str, scalar) if can_be_str else scalar
    if not is_list:
        return isinstance(value, allowed)
    return isinstance(value, list) and all(isinstance(x, allowed) for x in value)


def _as_yaml(value: str, can_be_str: bool, failure: str) -> Any:
    if not value:
        return value
    try:
        out = yaml.safe_load(value)
    except yaml.YAMLError as exc:
        if can_be_str:
            return value
        raise ValueError(f"{failure}: yaml.safe_load() failed\n{exc}") from None
    if not is_instance_of_valid_type(out, can_be_str=can_be_str):
        raise ValueError(f"{failure}: output type is not allowed, got {type(out)}")
    return out


def coerce_to_type(value: str, data_type: Any = None, *, can_be_str: bool = False) -> Any:
    """`value` as `data_type`, read by YAML's rules ('1' and '0' are booleans too); None:
    whatever YAML reads. With `can_be_str`, text that does not read as the type stays text.

    Raises ValueError when it cannot, TypeError when `value` is not a str."""
    ensure_argument_type(value, str, "value", "coerce_to_type")
    if data_type is None:
        return _as_yaml(value, can_be_str, f"Failed to convert '{value}' using yaml rules")
    scalar, is_list = extract_type(data_type)
    allowed = (str, scalar) if can_be_str else scalar
    if is_list:
        failure = f"Cannot convert value '{value}' to a list of '{allowed}'"
        out = _as_yaml(value, can_be_str, failure)
        if not isinstance(out, list) or not all(isinstance(x, allowed) for x in out):
            raise ValueError(failure + ("" if not isinstance(out, list) else f", got {out}"))
        return out
    if scalar is str:
        return value
    if scalar in (int, float):
        try:
            return scalar(value)
        except ValueError:
            if can_be_str:
                return value
            raise
    text = {"1": "true", "0": "false"}.get(value, value)  # bool: 1 and 0 count
    out = _as_yaml(text, can_be_str, f"Failed to convert '{value}' to '{scalar}'")
    if isinstance(out, allowed):
        return out
    raise ValueError(f"Cannot convert value '{value}' to '{scalar}'")


def coerce_list(value: list[str], data_type: Any = None, *, can_be_str: bool = False) -> Any:
    """Each text of `value` as `data_type` (a scalar type); the result must be uniform."""
    ensure_argument_type(value, list, "value", "coerce_list")
    out = [coerce_to_type(item, data_type, can_be_str=can_be_str) for item in value]
    if not is_instance_of_valid_type(out, can_be_str=can_be_str):
        raise ValueError(f"cannot convert value to {data_type}. Got value=`{value}`")
    return out


def get_typed_value(value: str | list[str], data_type: Any, *,
                    can_be_str: bool = False) -> Any:
    """A text or a list of texts as `data_type` (a list wants a `List[x]` type)."""
    if not isinstance(value, list):
        return coerce_to_type(value, data_type, can_be_str=can_be_str)
    if data_type is not None:
        data_type, is_list = extract_type(data_type)
        if not is_list:
            raise TypeError(f"Cannot convert input '{value}' of type '{type(value)}' to "
                            f"'{data_type}'")
    return coerce_list(value, data_type, can_be_str=can_be_str)


def is_substitution(x: Any) -> bool:
    """A substitution, or a non-empty list of substitutions and texts with one at least."""
    if isinstance(x, _AnySubstitution):
        return True
    if not isinstance(x, Iterable) or isinstance(x, str) or not len(x):  # type: ignore[arg-type]
        return False
    return all(isinstance(i, _AnySubstitution | str) for i in x) and \
        any(isinstance(i, _AnySubstitution) for i in x)


def is_normalized_substitution(x: Any) -> bool:
    """A non-empty list of substitutions only."""
    return isinstance(x, list) and bool(x) and all(isinstance(i, _AnySubstitution) for i in x)


def normalize_typed_substitution(value: Any, data_type: Any) -> Any:
    """A value of `data_type` kept as it is, substitutions as lists of them, to be performed
    and coerced later by perform_typed_substitution. A list mixing texts and substitutions is
    one substitution; `['a', [sub]]` is a list of two.

    Raises TypeError when the value can never be of `data_type`."""
    if isinstance(value, ScalarTypesTuple):
        if not is_instance_of(value, data_type):
            raise TypeError(f"value='{value}' is not an instance of {data_type}")
        return value
    if is_substitution(value):
        return normalize_to_list_of_substitutions(value)
    if not isinstance(value, Iterable):
        raise TypeError("value should be either a scalar, a substitutions, or a mixed list of "
                        f"scalars and substitutions. Got `value={value}` of type "
                        f"`{type(value)}`. ")
    kinds = {_item_kind(x, value) for x in value}
    data_type = _item_type(data_type, lambda scalar: TypeError(
        "The provided value resolves to a list, though the required type is a scalar. Got "
        f"value='{value}', data_type='{scalar}'."))
    return _normalize_list(list(value), kinds, data_type)


def _item_type(data_type: Any, refusal: Callable[[Any], Exception]) -> Any:
    """The type of the items of a list that `data_type` asks for (None: any);
    `refusal(the scalar type)` is raised when it asks for a scalar."""
    if data_type is None:
        return None
    scalar, is_list = extract_type(data_type)
    if not is_list:
        raise refusal(scalar)
    return scalar


def _item_kind(x: Any, value: Any) -> type:
    if isinstance(x, ScalarTypesTuple):
        return type(x)
    if is_substitution(x):
        return _AnySubstitution
    raise TypeError("value is a list, and one of the items is not a scalar, a Substitution or "
                    f"a list of substitutions. Got value='{value}'")


# The scalar types a uniform list may hold, by what it becomes (ints may be floats)
_UNIFORM = {str: {str}, bool: {bool}, int: {int}, float: {int, float}}


def _normalize_list(value: list[Any], kinds: set[type], data_type: Any) -> list[Any]:
    """Each item of a list: a scalar of the one kind the list holds, or substitutions."""
    if kinds == {_AnySubstitution}:  # substitutions only: they may become anything
        return [normalize_to_list_of_substitutions(x) for x in value]
    scalars = kinds - {_AnySubstitution}
    kind = next((k for k, allowed in _UNIFORM.items() if scalars <= allowed), None)
    if kind is None:
        raise TypeError(f"Input value is not an acceptable 'SomeValueType'.Got value='{value}'")
    if data_type not in (None, kind):
        raise TypeError(f"Got a list of '{kind}', expected a list of '{data_type}'. "
                        f"value='{value}'")
    cast = float if kind is float else (lambda x: x)
    return [normalize_to_list_of_substitutions(x) if is_substitution(x) else cast(x)
            for x in value]


def perform_typed_substitution(context: LaunchContext, value: Any, data_type: Any) -> Any:
    """Perform what normalize_typed_substitution made and coerce it to `data_type`.

    Raises TypeError for a scalar not of `data_type`, ValueError when the result is not."""
    if isinstance(value, ScalarTypesTuple):
        if data_type is not None and not is_instance_of(value, data_type):
            raise TypeError(f"value=`{value}` is a scalar and not an instance of `{data_type}`")
        return value
    if is_normalized_substitution(value):
        return coerce_to_type(perform_substitutions(context, value), data_type)
    if not isinstance(value, list):
        raise TypeError(f"Input value is not an acceptable 'NormalizedValueType'.Got "
                        f"value='{value}'")
    scalar = _item_type(data_type, lambda scalar: ValueError(
        "The input value is a list, cannot convert it to a scalar. Got "
        f"value='{value}', expected type {scalar}."))
    out = [coerce_to_type(perform_substitutions(context, x), scalar)
           if is_normalized_substitution(x) else x for x in value]
    if not is_instance_of(out, data_type):
        raise ValueError(f"The output list does not match the expected type Got value="
                         f"'{value}', expected type {scalar}." if scalar is not None else
                         "The output list is not uniform")
    return out


from launcher.compat.finder import rest_from_layout  # noqa: E402

__getattr__ = rest_from_layout(__name__)
