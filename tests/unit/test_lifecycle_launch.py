"""launch_ros's lifecycle parts in launch descriptions: the `lifecycle_node` tag in XML and
YAML, the Python names, and OnStateTransition's matching."""

from __future__ import annotations

from launcher.description.actions.lifecycle import (
    ChangeState,
    LifecycleNode,
    OnStateTransition,
    matches_action,
)
from launcher.runtime.lifecycle import StateTransition
from tests.support.launch_text import xml_description, yaml_description


def test_the_lifecycle_node_tag_in_xml_and_yaml():
    xml = xml_description('<launch><lifecycle_node pkg="p" exec="e" name="n" namespace="ns" '
                          'autostart="true"/></launch>')
    yaml = yaml_description("""
    launch:
      - lifecycle_node: {pkg: p, exec: e, name: n, namespace: ns}
    """)
    for description in (xml, yaml):
        (node,) = description.actions
        assert isinstance(node, LifecycleNode)


def test_on_state_transition_matches_its_node_and_states():
    node, other = object(), object()
    handler = OnStateTransition(target_lifecycle_node=node, goal_state="inactive",
                                entities=[])
    assert handler.matches(StateTransition(action=node, node="/n", start_state="configuring", goal_state="inactive"))
    assert not handler.matches(StateTransition(action=node, node="/n", start_state="activating", goal_state="active"))
    assert not handler.matches(StateTransition(action=other, node="/o", start_state="configuring", goal_state="inactive"))
    every = OnStateTransition(start_state="activating", entities=[])
    assert every.matches(StateTransition(action=other, node="/o", start_state="activating", goal_state="active"))
    change = ChangeState(lifecycle_node_matcher=matches_action(node), transition_id=3)
    assert change.matcher(node) and not change.matcher(other) and change.transition_id == 3


def test_the_python_names_are_launch_ros():
    from launcher import compat

    compat.enable_in_process()  # (as the Python launch file loader does)
    from launch.actions import EmitEvent  # noqa: F401 - (the shims, as a launch file has them)
    from launch.events import matches_action as shim_matches
    from launch_ros.actions import LifecycleNode as ShimNode
    from launch_ros.event_handlers import OnStateTransition as ShimHandler
    from launch_ros.events.lifecycle import ChangeState as ShimChange

    assert shim_matches is matches_action and ShimHandler is OnStateTransition
    assert ShimChange is ChangeState
    made = ShimNode(package="p", executable="e", name="n", namespace="", autostart=True)
    assert isinstance(made, LifecycleNode) and made.autostart is True


def test_a_lifecycle_node_without_a_name_is_said_where_it_is():
    import pytest

    from launcher.errors import LaunchError
    from tests.support.fake_service import run

    description = xml_description('<launch>\n<lifecycle_node pkg="p" exec="e" '
                                  'namespace="ns"/>\n</launch>', "lc.launch.xml")
    with pytest.raises(LaunchError, match="lifecycle_node needs a name") as caught:
        run(description)
    assert caught.value.location.line == 2
