"""The classes of launcher's own node API messages: what rosbags' type store generates
(`geometry_msgs__msg__Twist(linear=…, angular=…, __msgtype__=…)`, every field required,
numeric arrays as numpy arrays), made here without importing rosbags' type system (a fifth
of a node's start-up when it made its first message).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from launcher.records import Field


def make(type_name: str, names: list[str]) -> type:
    """The class of `type_name` (`pkg/msg/Name`) with these fields, in order."""
    names_t = tuple(names)
    count = len(names_t)
    known = frozenset(names_t)
    class_name = type_name.replace("/", "__")

    def __init__(self: Any, *args: Any, **kwargs: Any) -> None:  # noqa: N807
        if len(args) == count and not kwargs:  # how messages are read: the fast way
            self.__dict__.update(zip(names_t, args, strict=True))
            return
        if len(args) > count:
            raise TypeError(f"{class_name}.__init__() takes {count + 1} positional arguments "
                            f"but {len(args) + 1} were given")
        values = dict(zip(names_t, args, strict=False))
        for key, value in kwargs.items():
            if key not in known:
                raise TypeError(f"{class_name}.__init__() got an unexpected keyword argument "
                                f"'{key}'")
            if key in values:
                raise TypeError(f"{class_name}.__init__() got multiple values for argument "
                                f"'{key}'")
            values[key] = value
        if len(values) != count:
            missing = [n for n in names_t if n not in values]
            raise TypeError(f"{class_name}.__init__() missing {len(missing)} required "
                            f"argument{'s' if len(missing) > 1 else ''}: "
                            f"{', '.join(repr(n) for n in missing)}")
        self.__dict__.update((n, values[n]) for n in names_t)

    def __repr__(self: Any) -> str:  # noqa: N807
        shown = "".join(f"{n}={getattr(self, n)!r}, " for n in names_t)
        return f"{class_name}({shown}__msgtype__={type_name!r})"

    def __eq__(self: Any, other: Any) -> Any:  # noqa: N807
        if other.__class__ is not self.__class__:
            return NotImplemented
        return tuple(getattr(self, n) for n in names_t) == \
            tuple(getattr(other, n) for n in names_t)

    fields = {}
    for name in names_t:
        spec = Field()
        spec.name = name
        fields[name] = spec
    fields["__msgtype__"] = Field(default=type_name, init=False)  # (rosbags lists it too)
    fields["__msgtype__"].name = "__msgtype__"
    namespace: dict[str, Callable[..., Any] | Any] = {
        "__init__": __init__, "__repr__": __repr__, "__eq__": __eq__, "__hash__": None,
        "__msgtype__": type_name, "__dataclass_fields__": fields, "__match_args__": names_t,
        "__module__": __name__,
    }
    return type(class_name, (), namespace)
