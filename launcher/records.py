"""`@dataclass` for the modules `launcher launch` imports at start, without its import cost.

The standard library's decorator compiles an `__init__`, `__repr__` and `__eq__` per class
with `exec` and imports `inspect` first: for the launch's 33 classes that was a quarter of its
start-up. These classes get the same methods as closures over the class's fields instead. The
part of the interface launcher uses is here: `dataclass(init=, repr=, eq=, frozen=,
kw_only=)`, `field(default=, default_factory=, init=, repr=, compare=, kw_only=, metadata=)`,
`fields()`, `MISSING`, `__dataclass_fields__`, `__post_init__`, and fields inherited from
base classes made the same way. Mixing with `dataclasses` in one class tree is not supported.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from types import MappingProxyType
from typing import Any, TypeVar, dataclass_transform

T = TypeVar("T")


class _Missing:
    def __repr__(self) -> str:
        return "MISSING"


MISSING: Any = _Missing()
_EMPTY: Mapping[str, Any] = MappingProxyType({})


class FrozenInstanceError(AttributeError):
    pass


class Field:
    __slots__ = ("name", "type", "default", "default_factory", "init", "repr", "compare",
                 "kw_only", "metadata")

    def __init__(self, default: Any = MISSING, default_factory: Any = MISSING,
                 init: bool = True, repr: bool = True, compare: bool = True,  # noqa: A002
                 kw_only: Any = MISSING, metadata: Mapping[str, Any] | None = None) -> None:
        if default is not MISSING and default_factory is not MISSING:
            raise ValueError("cannot specify both default and default_factory")
        self.name = ""
        self.type: Any = None
        self.default, self.default_factory = default, default_factory
        self.init, self.repr, self.compare, self.kw_only = init, repr, compare, kw_only
        self.metadata = _EMPTY if metadata is None else MappingProxyType(dict(metadata))

    def __repr__(self) -> str:
        return f"Field(name={self.name!r}, default={self.default!r})"


def field(*, default: Any = MISSING, default_factory: Any = MISSING, init: bool = True,
          repr: bool = True, compare: bool = True, kw_only: Any = MISSING,  # noqa: A002
          metadata: Mapping[str, Any] | None = None) -> Any:
    return Field(default, default_factory, init, repr, compare, kw_only, metadata)


def fields(class_or_instance: Any) -> tuple[Field, ...]:
    try:
        return tuple(class_or_instance.__dataclass_fields__.values())
    except AttributeError:
        raise TypeError("must be called with a dataclass type or instance") from None


def is_record(obj: Any) -> bool:
    return hasattr(obj, "__dataclass_fields__")


@dataclass_transform(field_specifiers=(field, Field))
def dataclass(cls: type[T] | None = None, /, *, init: bool = True, repr: bool = True,  # noqa: A002
              eq: bool = True, frozen: bool = False,
              kw_only: bool = False) -> Any:
    def wrap(cls: type[T]) -> type[T]:
        return _process(cls, init, repr, eq, frozen, kw_only)

    return wrap if cls is None else wrap(cls)


def _is_class_var(annotation: Any) -> bool:
    text = annotation if isinstance(annotation, str) else getattr(annotation, "__name__", "")
    return text.startswith(("ClassVar", "typing.ClassVar"))


def _process(cls: type[T], init: bool, repr_: bool, eq: bool, frozen: bool,
             kw_only: bool) -> type[T]:
    all_fields: dict[str, Field] = {}
    for base in cls.__mro__[-1:0:-1]:
        all_fields.update(getattr(base, "__dataclass_fields__", {}))
    for name, annotation in cls.__dict__.get("__annotations__", {}).items():
        if _is_class_var(annotation):
            continue
        value = cls.__dict__.get(name, MISSING)
        spec = value if isinstance(value, Field) else Field(default=value)
        spec.name, spec.type = name, annotation
        if spec.kw_only is MISSING:
            spec.kw_only = kw_only
        if isinstance(value, Field):  # the class attribute becomes the default, or goes
            if spec.default is MISSING:
                delattr(cls, name)
            else:
                setattr(cls, name, spec.default)
        all_fields[name] = spec
    cls.__dataclass_fields__ = all_fields  # type: ignore[attr-defined]
    _check_order(cls, all_fields)
    explicit_hash = "__hash__" in cls.__dict__ and not (
        cls.__dict__["__hash__"] is None and "__eq__" in cls.__dict__)
    own = cls.__dict__  # methods the class body defines are kept, as dataclasses keeps them
    if init and "__init__" not in own:
        cls.__init__ = _make_init(cls, all_fields)  # type: ignore[assignment,misc]
    if repr_ and "__repr__" not in own:
        cls.__repr__ = _make_repr(all_fields)  # type: ignore[assignment,method-assign]
    if eq and "__eq__" not in own:
        cls.__eq__ = _make_eq(all_fields)  # type: ignore[assignment,method-assign]
    if eq and not explicit_hash:
        cls.__hash__ = _make_hash(all_fields) if frozen else None  # type: ignore
    if frozen:
        cls.__setattr__ = _frozen_setattr  # type: ignore[assignment,method-assign]
        cls.__delattr__ = _frozen_delattr  # type: ignore[assignment,method-assign]
    return cls


def _check_order(cls: type, all_fields: dict[str, Field]) -> None:
    seen_default = False
    for spec in all_fields.values():
        if not spec.init or spec.kw_only:
            continue
        has_default = spec.default is not MISSING or spec.default_factory is not MISSING
        if seen_default and not has_default:
            raise TypeError(f"{cls.__name__}: non-default argument '{spec.name}' follows "
                            f"default argument")
        seen_default = seen_default or has_default


def _make_init(cls: type, all_fields: dict[str, Field]) -> Callable[..., None]:
    positional = [f for f in all_fields.values() if f.init and not f.kw_only]
    keyword = [f for f in all_fields.values() if f.init and f.kw_only]
    derived = [f for f in all_fields.values() if not f.init and
               (f.default is not MISSING or f.default_factory is not MISSING)]
    post_init = getattr(cls, "__post_init__", None) is not None
    assign = object.__setattr__
    name = cls.__qualname__

    def value_of(spec: Field, kwargs: dict[str, Any]) -> Any:
        if spec.name in kwargs:
            return kwargs.pop(spec.name)
        if spec.default is not MISSING:
            return spec.default
        if spec.default_factory is not MISSING:
            return spec.default_factory()
        raise TypeError(f"{name}.__init__() missing required argument: '{spec.name}'")

    def __init__(self: Any, *args: Any, **kwargs: Any) -> None:  # noqa: N807
        if len(args) > len(positional):
            raise TypeError(f"{name}.__init__() takes {len(positional) + 1} positional "
                            f"arguments but {len(args) + 1} were given")
        for spec, value in zip(positional, args, strict=False):
            if spec.name in kwargs:
                raise TypeError(f"{name}.__init__() got multiple values for argument "
                                f"'{spec.name}'")
            assign(self, spec.name, value)
        for spec in positional[len(args):]:
            assign(self, spec.name, value_of(spec, kwargs))
        for spec in keyword:
            assign(self, spec.name, value_of(spec, kwargs))
        if kwargs:
            raise TypeError(f"{name}.__init__() got an unexpected keyword argument "
                            f"'{next(iter(kwargs))}'")
        for spec in derived:
            assign(self, spec.name, spec.default if spec.default is not MISSING
                   else spec.default_factory())
        if post_init:
            self.__post_init__()

    __init__.__qualname__ = f"{name}.__init__"
    return __init__


def _make_repr(all_fields: dict[str, Field]) -> Callable[[Any], str]:
    shown = [f.name for f in all_fields.values() if f.repr]

    def __repr__(self: Any) -> str:  # noqa: N807
        values = ", ".join(f"{n}={getattr(self, n, MISSING)!r}" for n in shown)
        return f"{type(self).__qualname__}({values})"

    return __repr__


def _make_eq(all_fields: dict[str, Field]) -> Callable[[Any, Any], Any]:
    compared = [f.name for f in all_fields.values() if f.compare]

    def __eq__(self: Any, other: Any) -> Any:  # noqa: N807
        if other.__class__ is not self.__class__:
            return NotImplemented
        return tuple(getattr(self, n) for n in compared) == \
            tuple(getattr(other, n) for n in compared)

    return __eq__


def _make_hash(all_fields: dict[str, Field]) -> Callable[[Any], int]:
    compared = [f.name for f in all_fields.values() if f.compare]

    def __hash__(self: Any) -> int:  # noqa: N807
        return hash(tuple(getattr(self, n) for n in compared))

    return __hash__


def _frozen_setattr(self: Any, name: str, value: Any) -> None:
    raise FrozenInstanceError(f"cannot assign to field '{name}'")


def _frozen_delattr(self: Any, name: str) -> None:
    raise FrozenInstanceError(f"cannot delete field '{name}'")


def replace(obj: T, **changes: Any) -> T:
    """A copy of `obj` with some fields changed (through `__init__`, as dataclasses does)."""
    for spec in fields(obj):
        if spec.init and spec.name not in changes:
            changes[spec.name] = getattr(obj, spec.name)
    return type(obj)(**changes)


def asdict(obj: Any) -> dict[str, Any]:
    """The fields as a dict (records within it too, and their lists, tuples and dicts)."""
    def convert(value: Any) -> Any:
        if is_record(value) and not isinstance(value, type):
            return {spec.name: convert(getattr(value, spec.name)) for spec in fields(value)}
        if isinstance(value, list | tuple):
            return type(value)(convert(v) for v in value)
        if isinstance(value, dict):
            return {convert(k): convert(v) for k, v in value.items()}
        return value

    return convert(obj)
