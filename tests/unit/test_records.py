"""launcher.records against the standard library's dataclasses, on the features it offers."""

from __future__ import annotations

import dataclasses
from typing import ClassVar

import pytest

from launcher import records


def both(**options):
    """The same class body under both decorators."""
    def make(module):
        @module.dataclass(**options)
        class Point:
            x: int
            y: int = 2
            tags: list = module.field(default_factory=list)
            hidden: str = module.field(default="h", repr=False, compare=False)
            kind: ClassVar[str] = "point"

        return Point

    return make(dataclasses), make(records)


@pytest.mark.parametrize("options", [{}, {"frozen": True}, {"eq": False}, {"kw_only": True}])
def test_init_repr_eq_and_hash_match_dataclasses(options):
    std, ours = both(**options)
    args = {"x": 1, "tags": ["a"]}
    a, b = std(**args), ours(**args)
    assert repr(a) == repr(b)  # (both classes have the same qualified name)
    assert (ours(**args) == ours(**args)) == (std(**args) == std(**args))
    assert (ours(**args, hidden="other") == b) == (std(**args, hidden="other") == a)
    assert (ours.__hash__ is None) == (std.__hash__ is None)
    if options.get("frozen"):
        assert hash(ours(x=1, tags=(1,))) == hash(ours(x=1, tags=(1,))) == \
            hash(ours(x=1, tags=(1,), hidden="not compared"))
        with pytest.raises(AttributeError):
            b.x = 5
    assert [f.name for f in records.fields(ours)] == [f.name for f in dataclasses.fields(std)]
    assert ours.kind == "point" and "kind" not in ours.__dataclass_fields__


def test_arguments_are_checked_like_a_written_init():
    _, ours = both()
    assert ours(1, 3).y == 3 and ours(1).tags == [] and ours(1).tags is not ours(1).tags
    with pytest.raises(TypeError, match="missing required argument: 'x'"):
        ours()
    with pytest.raises(TypeError, match="unexpected keyword argument 'z'"):
        ours(1, z=3)
    with pytest.raises(TypeError, match="multiple values for argument 'x'"):
        ours(1, x=2)
    with pytest.raises(TypeError, match="positional arguments"):
        ours(1, 2, [], "h", 5)
    _, keyword_only = both(kw_only=True)
    with pytest.raises(TypeError):
        keyword_only(1)


def test_inheritance_post_init_init_false_metadata_replace_and_asdict():
    @records.dataclass(kw_only=True, eq=False)
    class Base:
        where: str | None = records.field(default=None, repr=False, metadata={"m": 1})

        def __post_init__(self):
            self.seen = True

    @records.dataclass(kw_only=True, eq=False)
    class Child(Base):
        name: str
        count: int = records.field(init=False, default=0)

    child = Child(name="n", where="w")
    assert (child.name, child.where, child.count, child.seen) == ("n", "w", 0, True)
    assert [f.name for f in records.fields(child)] == ["where", "name", "count"]
    assert Child.__dataclass_fields__["where"].metadata["m"] == 1
    assert child != Child(name="n", where="w")  # eq=False: identity
    changed = records.replace(child, name="m")
    assert (changed.name, changed.where) == ("m", "w")
    assert records.asdict(changed) == {"where": "w", "name": "m", "count": 0}
    assert "where" not in repr(child) and "name='n'" in repr(child)


def test_a_field_without_a_default_after_one_with_is_refused():
    with pytest.raises(TypeError, match="non-default argument 'b'"):
        @records.dataclass
        class Bad:
            a: int = 1
            b: int
