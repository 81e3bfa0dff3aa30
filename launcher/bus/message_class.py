"""The classes of launcher's own node API messages: what rosbags' type store generates
(`geometry_msgs__msg__Twist(linear=…, angular=…, __msgtype__=…)`, every field required,
numeric arrays as numpy arrays), made here without importing rosbags' type system (a fifth
of a node's start-up when it made its first message).
"""

from __future__ import annotations

from collections.abc import Callable
from types import CodeType, FunctionType
from typing import Any

from launcher.records import Field

_TEMPLATES: dict[int, CodeType] = {}


def make(type_name: str, names: list[str]) -> type:
    """The class of `type_name` (`pkg/msg/Name`) with these fields, in order."""
    names_t = tuple(names)
    class_name = type_name.replace("/", "__")

    init = assigner(names_t, f"{class_name}.__init__")

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
        "__init__": init, "__repr__": __repr__, "__eq__": __eq__, "__hash__": None,
        "__msgtype__": type_name, "__dataclass_fields__": fields, "__match_args__": names_t,
        "__module__": __name__,
    }
    return type(class_name, (), namespace)


def assigner(names: tuple[str, ...], qualname: str = "assign") -> Callable[..., None]:
    """`f(obj, v0, v1, …)` setting `obj.<names[i]> = vi`, as fast as written-out code."""
    return FunctionType(_init_code(len(names)).replace(
        co_names=names, co_varnames=("_self_", *names), co_name=qualname.rpartition(".")[2],
        co_qualname=qualname), {})


def _init_code(count: int) -> CodeType:
    """`def __init__(self, f0, f1, …): self.f0 = f0; …` for `count` fields: launcher's own
    text, compiled once per count; a class gets it with its field names put in as the
    argument and attribute names (never into source: a package's .msg is user text). As fast
    as the `__init__` rosbags and dataclasses write, with Python's own argument errors."""
    code = _TEMPLATES.get(count)
    if code is None:
        arguments = "".join(f", f{i}" for i in range(count))
        body = "".join(f"    self.f{i} = f{i}\n" for i in range(count)) or "    pass\n"
        namespace: dict[str, Any] = {}
        exec(compile(f"def __init__(self{arguments}):\n{body}", "<message_class>", "exec"),
             namespace)
        code = _TEMPLATES[count] = namespace["__init__"].__code__
        assert code.co_names == tuple(f"f{i}" for i in range(count)), code.co_names
    return code
