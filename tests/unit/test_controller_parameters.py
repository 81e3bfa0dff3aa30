"""Parameters declared as data (bus/declarations.py), as the controllers and built-in nodes
declare theirs: read, checked and described from the declaration alone."""

from __future__ import annotations

import math

import pytest

from launcher.bus.declarations import REQUIRED, Param, descriptor, read, refusal
from launcher.control.controllers import TYPES, controller_class
from launcher.errors import LaunchError, ParameterError, report

DECLARED = (
    Param("joints", "string_array", REQUIRED, "the joints", non_empty=True),
    Param("rate", "double", 20.0, "checks a second", minimum=1e-3),
    Param("window", "int", 10, "updates", minimum=1, maximum=100),
    Param("gains.{joints}.p", "double", 0.0, "proportional"),
)


def test_defaults_fill_what_the_file_leaves_out_and_placeholders_expand_per_joint():
    values = read(DECLARED, {"joints": ["a", "b"], "gains.b.p": 2})
    assert values == {"joints": ["a", "b"], "rate": 20.0, "window": 10, "gains.a.p": 0.0,
                      "gains.b.p": 2.0}


def test_an_integer_is_taken_for_a_double_and_made_one():
    assert isinstance(read(DECLARED, {"joints": ["a"], "rate": 5})["rate"], float)


def test_a_missing_required_parameter_is_refused_by_name():
    with pytest.raises(ParameterError, match="parameter 'joints' is required"):
        read(DECLARED, {})


def test_a_value_of_the_wrong_type_is_refused_with_what_was_expected():
    with pytest.raises(ParameterError, match=r"parameter 'window': expected a whole number, "
                                             r"got 'ten'"):
        read(DECLARED, {"joints": ["a"], "window": "ten"})


def test_a_value_out_of_its_bounds_is_refused_with_the_bound():
    with pytest.raises(ParameterError, match="parameter 'window': expected a number ≤ 100, "
                                             "got 500"):
        read(DECLARED, {"joints": ["a"], "window": 500})


def test_an_empty_list_that_must_name_something_is_refused():
    with pytest.raises(ParameterError, match="parameter 'joints' is empty"):
        read(DECLARED, {"joints": []})


def test_only_the_named_parameters_are_read():
    assert read(DECLARED, {"joints": ["a"], "window": "bad"}, ("joints",)) == {"joints": ["a"]}


def test_the_descriptor_carries_type_description_bounds_and_read_only():
    fields = descriptor("window", DECLARED[2])
    assert fields["type"] == 2 and fields["description"] == "updates"
    assert fields["integer_range"] == [{"from_value": 1, "to_value": 100, "step": 0}]
    open_above = descriptor("rate", DECLARED[1])["floating_point_range"][0]
    assert open_above["from_value"] == 1e-3 and open_above["to_value"] == math.inf


@pytest.mark.parametrize("type_name", sorted(TYPES))
def test_every_controller_declares_its_parameters(type_name):
    declared = controller_class(type_name).PARAMETERS
    assert declared and all(p.description for p in declared)
    assert len({p.name for p in declared}) == len(declared)


CHOSEN = (Param("interpolation_method", "string", "splines", "how",
                choices=("splines", "none")),)


def test_a_text_outside_its_choices_is_refused_with_them_and_a_suggestion():
    with pytest.raises(ParameterError, match=r"parameter 'interpolation_method': expected one "
                                             r"of splines, none, got 'spline' \(did you mean "
                                             r"'splines'\?\)"):
        read(CHOSEN, {"interpolation_method": "spline"})


def test_a_set_from_outside_of_another_type_is_refused_in_rclcpps_words():
    assert refusal("rate", DECLARED[1], "fast") == (
        "Wrong parameter type, parameter {rate} is of type {double}, setting it to {string} "
        "is not allowed.")


def test_a_set_from_outside_beyond_the_range_is_refused_in_rclcpps_words():
    assert refusal("window", DECLARED[2], 500) == \
        "Parameter {window} doesn't comply with integer range."


def test_a_set_from_outside_that_fits_the_declaration_is_taken():
    assert refusal("rate", DECLARED[1], 5) is None


def test_a_node_refuses_a_set_that_does_not_fit_what_it_declared():
    from launcher.bus.node_parameters import NodeParameters

    params = NodeParameters({"joints": ["a"]}, "/n")
    params.declare(DECLARED)
    assert "Wrong parameter type" in params.request("rate", "fast")
    assert params.get("rate") == 20.0


def test_the_trajectory_controllers_feed_forward_is_off_unless_set_as_in_ros():
    declared = controller_class("joint_trajectory_controller/JointTrajectoryController")
    scale = next(p for p in declared.PARAMETERS if p.name.endswith("ff_velocity_scale"))
    assert scale.default == 0.0


BOUNDED = (Param("wheel_radius", "double", REQUIRED, "m", above=0.0),
           Param("slip", "double", 0.0, "a share", minimum=0.0, below=1.0),
           Param("teeth", "int", 10, "a count", above=2, below=100))


@pytest.mark.parametrize("values, expected", [
    ({"wheel_radius": 0.0}, "parameter 'wheel_radius': expected a number > 0, got 0.0"),
    ({"wheel_radius": -1}, "parameter 'wheel_radius': expected a number > 0, got -1.0"),
    ({"wheel_radius": 0.1, "slip": 1}, "parameter 'slip': expected a number < 1, got 1.0"),
    ({"wheel_radius": 0.1, "teeth": 2}, "parameter 'teeth': expected a number > 2, got 2"),
], ids=["zero", "negative", "at-the-top", "int"])
def test_an_exclusive_bound_refuses_the_bound_itself(values, expected):
    with pytest.raises(ParameterError) as caught:
        read(BOUNDED, values)
    assert str(caught.value) == expected


def test_a_value_inside_exclusive_bounds_is_taken_and_described_as_ros_can():
    assert read(BOUNDED, {"wheel_radius": 1e-9, "slip": 0.0, "teeth": 3})["teeth"] == 3
    radius = descriptor("wheel_radius", BOUNDED[0])
    assert radius["floating_point_range"][0]["from_value"] == 0.0
    assert radius["additional_constraints"] == "greater than 0"
    assert descriptor("teeth", BOUNDED[2])["integer_range"] == [
        {"from_value": 3, "to_value": 99, "step": 0}]  # whole numbers: > 2 is ≥ 3


LISTED = (Param("capabilities", "string_array", ["services"], "what clients may do",
                choices=("services", "assets")),)


def test_each_string_of_an_array_must_be_one_of_its_choices():
    assert read(LISTED, {"capabilities": ["assets", "services"]}) == \
        {"capabilities": ["assets", "services"]}
    with pytest.raises(ParameterError, match=r"parameter 'capabilities': expected one of "
                                             r"services, assets, got 'asets' \(did you mean "
                                             r"'assets'\?\)"):
        read(LISTED, {"capabilities": ["services", "asets"]})


def test_a_parameter_error_names_its_node_once_and_is_a_launch_error(capsys):
    from launcher.bus.node_parameters import NodeParameters

    params = NodeParameters({"joints": ["a"], "rate": 0}, "/robot/joint_state_publisher")
    with pytest.raises(LaunchError) as caught:
        params.declare(DECLARED)
    assert isinstance(caught.value, ParameterError) and caught.value.name == "rate"
    assert str(caught.value) == ("/robot/joint_state_publisher: parameter 'rate': expected a "
                                 "number ≥ 0.001, got 0.0")
    assert report(caught.value, "joint_state_publisher") == 1  # (another node's label: kept)
    assert capsys.readouterr().err.startswith("[joint_state_publisher] error: /robot/")
    named = ParameterError("rate", "parameter 'rate': expected …", "/joint_state_publisher")
    report(named, "joint_state_publisher")  # its own node's label: said once
    assert capsys.readouterr().err == ("error: /joint_state_publisher: parameter 'rate': "
                                       "expected …\n")
