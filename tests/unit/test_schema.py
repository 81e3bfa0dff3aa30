"""The one record builder every config of launcher declares with (launcher/schema.py)."""

from __future__ import annotations

import math

import pytest

from launcher.errors import ParseError
from launcher.records import dataclass
from launcher.schema import Kind, attr, build


@dataclass
class Record:
    name: str = attr(Kind.TEXT, "", required=True, aliases=("entity",))
    mode: str = attr(Kind.TEXT, "fast", choices=("fast", "slow"))
    count: int = attr(Kind.INT, 1, minimum=1)
    rate: float = attr(Kind.FLOAT, 20.0, minimum=0.0, maximum=1000.0)
    on: bool = attr(Kind.BOOL, False)
    joints: list[str] = attr(Kind.NAMES)


def test_values_from_yaml_or_text_are_coerced_and_aliases_accepted():
    record = build(Record, {"entity": "bot", "count": "3", "rate": 5, "on": "yes",
                            "joints": "left"})
    assert (record.name, record.count, record.rate, record.on) == ("bot", 3, 5.0, True)
    assert record.joints == ["left"] and record.mode == "fast"
    assert build(Record, {"name": "x", "joints": ["a", "b"], "on": True}).joints == ["a", "b"]


@pytest.mark.parametrize("values, expected", [
    ({"name": "x", "cuont": 2}, "f.yaml:3: unknown key 'cuont' (did you mean 'count'?); "
                                "expected name, mode, count, rate, on, joints"),
    ({}, "f.yaml:3: name is required"),
    ({"name": "x", "mode": "fsat"}, "mode: expected one of fast, slow, got 'fsat' "
                                    "(did you mean 'fast'?)"),
    ({"name": "x", "count": 0}, "count: expected a number ≥ 1, got 0"),
    ({"name": "x", "count": 1.5}, "count: expected a whole number, got 1.5"),
    ({"name": "x", "rate": "2000"}, "rate: expected a number ≤ 1000, got 2000"),
    ({"name": "x", "rate": "nan"}, "rate: expected a finite number, got 'nan'"),
    ({"name": "x", "on": "maybe"}, "on: expected true or false, got 'maybe'"),
    ({"name": "x", "on": 3}, "on: expected true or false, got 3"),
], ids=["unknown", "required", "choice", "minimum", "whole", "maximum", "nan", "bool", "typed"])
def test_bad_values_say_where_what_and_what_was_expected(values, expected):
    with pytest.raises(ParseError) as caught:
        build(Record, values, "f.yaml:3")
    assert expected in str(caught.value)


def test_unknown_keys_may_be_warned_about_or_ignored():
    said: list[str] = []
    record = build(Record, {"name": "x", "extra": 1}, "p", unknown="warn", warn=said.append)
    assert record.name == "x" and len(said) == 1 and "unknown key 'extra'" in said[0]
    assert build(Record, {"name": "x", "use_sim_time": True}, unknown="ignore").name == "x"
    assert math.isclose(build(Record, {"name": "x"}).rate, 20.0)


@dataclass
class Bounded:
    radius: float = attr(Kind.FLOAT, 0.1, above=0.0)
    share: float = attr(Kind.FLOAT, 0.5, minimum=0.0, below=1.0)
    sides: list[str] = attr(Kind.NAMES, choices=("left", "right"))


@pytest.mark.parametrize("values, expected", [
    ({"radius": 0}, "radius: expected a number > 0, got 0"),
    ({"radius": "-0.5"}, "radius: expected a number > 0, got -0.5"),
    ({"share": 1.0}, "share: expected a number < 1, got 1.0"),
    ({"sides": ["left", "rihgt"]}, "sides: expected one of left, right, got 'rihgt' "
                                   "(did you mean 'right'?)"),
    ({"sides": "middle"}, "sides: expected one of left, right, got 'middle'"),
], ids=["above", "above-text", "below", "each-choice", "one-choice"])
def test_exclusive_bounds_and_each_names_choice_are_checked(values, expected):
    with pytest.raises(ParseError) as caught:
        build(Bounded, values)
    assert str(caught.value) == expected


def test_values_inside_exclusive_bounds_and_chosen_names_are_taken():
    record = build(Bounded, {"radius": "1e-9", "share": 0, "sides": ["right", "left"]})
    assert (record.radius, record.share, record.sides) == (1e-9, 0.0, ["right", "left"])


def test_fields_and_parameters_are_checked_by_one_check_in_one_wording():
    from launcher.bus.declarations import Param
    from launcher.schema import problem

    field = attr(Kind.FLOAT, above=0.0).metadata["launch"]
    param = Param("radius", "double", 1.0, above=0.0)
    assert problem(0.0, field, "radius") == problem(0.0, param, "radius") == \
        "radius: expected a number > 0, got 0.0"
    assert problem(None, Param("joints", "string_array"), "joints") == "joints is required"
    assert problem(None, field, "radius") is None
