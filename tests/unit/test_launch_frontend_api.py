"""launch.frontend's API: a user's class exposed with `@expose_action` / `@expose_substitution`
becomes a tag / a `$(name …)` of launcher's XML and YAML files (through launcher's registry
and loader), launch_xml's and launch_yaml's entities and parsers, and launch's type coercion
(launch.utilities.type_utils)."""

from __future__ import annotations

from types import SimpleNamespace

import pytest

from launcher import compat
from launcher.errors import ParseError
from launcher.frontend.loader import load_file
from tests.support.fake_service import run


@pytest.fixture(scope="module")
def exposed():
    """The user's extension: a `greet` tag and a `$(shout …)` substitution (exposed once: the
    registry is the process's)."""
    compat.enable_in_process()
    from launch import Action, Substitution
    from launch.frontend import expose_action, expose_substitution
    from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

    @expose_action("test_frontend_api_greet")
    class Greet(Action):
        def __init__(self, *, whom, times=1, **kwargs):
            super().__init__(**kwargs)
            self.whom, self.times = whom, times

        @classmethod
        def parse(cls, entity, parser):
            kwargs = {"whom": parser.parse_substitution(entity.get_attr("whom"))}
            times = entity.get_attr("times", data_type=int, optional=True, can_be_str=False)
            if times is not None:
                kwargs["times"] = times
            return cls, kwargs

        def execute(self, context):
            context.greeted = getattr(context, "greeted", [])
            context.greeted += [perform_substitutions(context, self.whom)] * self.times

    @expose_substitution("test_frontend_api_shout")
    class Shout(Substitution):
        def __init__(self, text):
            super().__init__()
            self.text = normalize_to_list_of_substitutions(text)

        @classmethod
        def parse(cls, data):
            if len(data) != 1:
                raise TypeError("shout takes one argument")
            return cls, {"text": data[0]}

        def perform(self, context):
            return perform_substitutions(context, self.text).upper()

    return SimpleNamespace(Greet=Greet, Shout=Shout)


XML = """<launch>
  <arg name="who" default="world"/>
  <test_frontend_api_greet whom="$(test_frontend_api_shout $(var who))" times="2"/>
  <test_frontend_api_greet whom="nobody" if="false"/>
</launch>
"""
YAML = """launch:
- arg: {name: who, default: world}
- test_frontend_api_greet: {whom: "$(test_frontend_api_shout $(var who))", times: 2}
- test_frontend_api_greet: {whom: nobody, if: "false"}
"""


@pytest.mark.parametrize("name, text", [("a.launch.xml", XML), ("a.launch.yaml", YAML)],
                         ids=["xml", "yaml"])
def test_an_exposed_action_and_substitution_run_from_a_launch_file(exposed, tmp_path, name,
                                                                   text):
    path = tmp_path / name
    path.write_text(text)
    description = load_file(path)
    greets = [a for a in description.actions if isinstance(a, exposed.Greet)]
    assert [g.times for g in greets] == [2, 1]
    assert greets[0].where.line == 3
    context, _ = run(description)
    assert context.greeted == ["WORLD", "WORLD"]  # (the second's `if` is false)


@pytest.mark.parametrize("name, text, message", [
    ("b.launch.xml", '<launch><test_frontend_api_greet whom="x" colour="red"/></launch>',
     "Unexpected attribute"),
    ("b.launch.yaml", "launch:\n- test_frontend_api_greet: {whom: x, colour: red}\n",
     "Unexpected key"),
    ("c.launch.xml", '<launch><test_frontend_api_greet whom="x" times="many"/></launch>',
     "times"),
    ("c.launch.yaml", "launch:\n- test_frontend_api_greet: {whom: x, times: '2'}\n", "times"),
    ("d.launch.xml", '<launch><test_frontend_api_greet whom="$(test_frontend_api_shout)"/>'
     "</launch>", "shout takes one argument"),
], ids=["xml-leftover", "yaml-leftover", "xml-type", "yaml-type", "substitution-arguments"])
def test_what_an_exposed_parse_refuses_is_an_error_at_the_tag(exposed, tmp_path, name, text,
                                                             message):
    path = tmp_path / name
    path.write_text(text)
    with pytest.raises(ParseError, match=message) as caught:
        load_file(path)
    assert caught.value.location.file == str(path)


def test_a_name_is_exposed_once(exposed):
    from launch.frontend import expose_action

    expose_action("test_frontend_api_greet")(exposed.Greet)  # the same parse again: a no-op
    with pytest.raises(RuntimeError, match="defined twice"):
        expose_action("executable")(exposed.Greet)  # (launcher's own tag)
    with pytest.raises(RuntimeError, match="class method called 'parse'"):
        expose_action("test_frontend_api_nothing")(type("Plain", (), {}))


def test_launch_xml_and_launch_yaml_parse_their_files(exposed, tmp_path):
    from launch.frontend import Parser

    for name, text, frontend in (("e.launch.xml", XML, "launch_xml.parser"),
                                 ("e.launch.yaml", YAML, "launch_yaml.parser")):
        path = tmp_path / name
        path.write_text(text)
        root, parser = Parser.load(str(path))
        assert type(parser).__module__ == frontend
        description = parser.parse_description(root)
        assert sum(isinstance(a, exposed.Greet) for a in description.actions) == 2


def test_entities_type_their_attributes_each_as_its_format_does():
    compat.enable_in_process()
    import xml.etree.ElementTree as ET

    import launch_xml
    import launch_yaml
    from launch.frontend import Entity

    xml = launch_xml.Entity(ET.fromstring('<node n="3" l="1,2" l-sep="," q="x"><env a="b"/>'
                                          '</node>'))
    assert xml.get_attr("n", data_type=int) == 3
    assert xml.get_attr("l", data_type=list[int]) == [1, 2]
    assert xml.get_attr("q", data_type=int) == "x"  # (can be a str: substitutions)
    with pytest.raises(TypeError):
        xml.get_attr("q", data_type=int, can_be_str=False)
    assert [e.get_attr("a") for e in xml.get_attr("env", data_type=list[Entity])] == ["b"]
    xml.assert_entity_completely_parsed()

    yaml = launch_yaml.Entity({"n": 3, "s": "3", "l": [1, 2], "children": [{"log": {}}]}, "g")
    assert yaml.get_attr("n", data_type=int) == 3
    with pytest.raises(TypeError):
        yaml.get_attr("s", data_type=int, can_be_str=False)  # ('3' is a str in YAML)
    assert yaml.get_attr("l", data_type=list[int]) == [1, 2]
    with pytest.raises(ValueError, match="children"):
        yaml.assert_entity_completely_parsed()
    assert [c.type_name for c in yaml.children] == ["log"]
    yaml.assert_entity_completely_parsed()
    assert yaml.get_attr("missing", optional=True) is None
    with pytest.raises(AttributeError):
        yaml.get_attr("missing")


@pytest.mark.parametrize("value, data_type, expected", [
    ("1", int, 1), ("1.5", float, 1.5), ("1", float, 1.0), ("true", bool, True),
    ("1", bool, True), ("0", bool, False), ("1", str, "1"), ("[1, 2]", list[int], [1, 2]),
    ("[a, b]", list[str], ["a", "b"]), ("2", None, 2), ("on", None, True), ("", None, ""),
    ("abc", None, "abc"), ("[1, 'a']", list[int], ValueError), ("x", int, ValueError),
    ("2", bool, ValueError), ("{a: 1}", None, ValueError),
], ids=lambda v: repr(v))
def test_coerce_to_type_reads_text_by_yamls_rules(value, data_type, expected):
    compat.enable_in_process()
    from launch.utilities.type_utils import coerce_to_type

    if expected is ValueError:
        with pytest.raises(ValueError):
            coerce_to_type(value, data_type)
    else:
        got = coerce_to_type(value, data_type)
        assert got == expected and type(got) is type(expected)


def test_coerce_keeps_text_when_it_may_be_a_str_and_refuses_what_is_not_text():
    compat.enable_in_process()
    from launch.utilities.type_utils import coerce_list, coerce_to_type, get_typed_value

    assert coerce_to_type("x", int, can_be_str=True) == "x"
    assert coerce_to_type("[1, x]", list[int], can_be_str=True) == [1, "x"]
    assert coerce_list(["1", "2"], int) == [1, 2]
    assert get_typed_value(["1", "2"], list[float]) == [1.0, 2.0]
    with pytest.raises(TypeError):
        coerce_to_type(1, int)
    with pytest.raises(TypeError):
        get_typed_value(["1"], int)


def test_typed_substitutions_are_normalized_then_performed_and_coerced():
    compat.enable_in_process()
    from launch.substitutions import LaunchConfiguration, TextSubstitution
    from launch.utilities.type_utils import (
        is_substitution,
        normalize_typed_substitution,
        perform_typed_substitution,
    )

    from launcher.runtime.context import LaunchContext

    context = LaunchContext({}, {"n": "3"})
    n = normalize_typed_substitution(LaunchConfiguration("n"), int)
    assert perform_typed_substitution(context, n, int) == 3
    mixed = normalize_typed_substitution([1, LaunchConfiguration("n")], list[int])
    assert perform_typed_substitution(context, mixed, list[int]) == [1, 3]
    assert normalize_typed_substitution(2.5, float) == 2.5
    with pytest.raises(TypeError):
        normalize_typed_substitution("x", int)
    with pytest.raises(TypeError):
        normalize_typed_substitution([1, "a"], None)
    assert is_substitution(["a", TextSubstitution(text="b")]) and not is_substitution(["a"])
