"""The substitution base: a small immutable value with one verb, `perform(context) -> str`."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any, ClassVar

from launcher import records
from launcher.errors import Location, SubstitutionError
from launcher.records import dataclass, field
from launcher.runtime.context import LaunchContext


@dataclass(frozen=True)
class Substitution:
    where: Location | None = field(default=None, compare=False, kw_only=True, repr=False)
    names: ClassVar[tuple[str, ...]] = ()  # the `$(name …)` spellings; set by @substitution

    def perform(self, context: LaunchContext) -> str:
        raise NotImplementedError

    def fail(self, message: str) -> SubstitutionError:
        return SubstitutionError(message, self.where)

    @classmethod
    def from_args(cls, args: list[Text_], where: Location | None) -> Substitution:
        """Build from `$(name a b …)` arguments, mapped in order onto the dataclass fields."""
        params = [f for f in records.fields(cls) if f.init and not f.kw_only]
        required = [f for f in params if f.default is records.MISSING]
        name = cls.names[0] if cls.names else cls.__name__
        if not len(required) <= len(args) <= len(params):
            expected = _arity(params, required)
            raise SubstitutionError(
                f"$({name}) takes {expected}, got {len(args)}: "
                f"$({name} {' '.join(f.name.upper() for f in params)})".replace(" )", ")"),
                where,
            )
        return cls(*args, where=where)

    def describe(self) -> str:
        values = [v for f in records.fields(self) if f.init and not f.kw_only
                  if (v := getattr(self, f.name)) is not None]
        args = " ".join(_quote(describe_text(v)) if isinstance(v, tuple) else str(v)
                        for v in values)
        return f"$({self.names[0]}{' ' + args if args else ''})"


def _arity(params: list[Any], required: list[Any]) -> str:
    if len(params) == len(required):
        return f"{len(params)} argument{'s' if len(params) != 1 else ''}"
    return f"{len(required)} to {len(params)} arguments"


def _quote(text: str) -> str:
    return f"'{text}'" if (" " in text or not text) else text


@dataclass(frozen=True)
class Text(Substitution):
    """Literal text."""

    text: str

    def perform(self, context: LaunchContext) -> str:
        return self.text

    def describe(self) -> str:
        return self.text


# A value that substitutions make: the concatenation of its parts.
Text_ = tuple[Substitution, ...]


def perform_text(context: LaunchContext, text: Text_) -> str:
    if len(text) == 1:
        value = text[0].perform(context)
        return value if isinstance(value, str) else _not_text(text[0], value)
    values = [s.perform(context) for s in text]
    try:
        return "".join(values)
    except TypeError:  # a substitution of the user's gave something else than text
        sub, value = next((s, v) for s, v in zip(text, values, strict=True)
                          if not isinstance(v, str))
        return _not_text(sub, value)


def _not_text(sub: Substitution, value: object) -> str:
    """A substitution of the user's own whose perform() gave something else than text."""
    from launcher.description.made_by_code import defined_at

    raise SubstitutionError(f"{type(sub).__name__}.perform() returned {value!r:.60} "
                            f"({type(value).__name__}); a substitution returns text (str)",
                            defined_at(type(sub).perform))


def describe_text(text: Text_) -> str:
    return "".join(s.describe() for s in text)


def is_literal(text: Text_) -> bool:
    return all(isinstance(s, Text) for s in text)


def to_text(value: Any) -> Text_:
    """Normalize what the Python API accepts (str, number, substitution, lists) to a Text_."""
    if isinstance(value, tuple) and all(isinstance(v, Substitution) for v in value):
        return value
    if isinstance(value, Substitution):
        return (value,)
    if isinstance(value, bool):
        return (Text(str(value).lower()),)
    if isinstance(value, str | int | float):
        return (Text(str(value)),)
    if isinstance(value, Iterable):
        return tuple(s for item in value for s in to_text(item))
    raise TypeError(f"expected text or a substitution, got {type(value).__name__}")


def substitution(*names: str):
    """Mark a class as the substitution `$(name …)`; the registry collects it."""

    def mark(cls: type[Substitution]) -> type[Substitution]:
        cls.names = names
        return cls

    return mark
