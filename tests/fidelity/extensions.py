"""launcher's extensions: what a ROS 2 launch file may say beyond ROS 2's own launch. Real
`ros2 launch` refuses a file that uses one, so such a file says so once: XML
`<launch extensions="launcher">`, YAML `extensions: [launcher]` beside `launch:`, Python by
importing from `launcher.api.extensions`. The fidelity page lists them from this table
(docs/_gen/reference_fidelity.py), and a unit test holds it to what the registry marks as
extensions (tests/unit/test_machines.py).
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Extension:
    what: str
    xml: str  # how XML writes it (YAML writes the same tags and attributes)
    python: str
    why: str
    tags: tuple[str, ...] = ()  # the tags it adds
    attributes: tuple[tuple[str, str], ...] = ()  # the (tag, attribute) pairs it adds


EXTENSIONS = (
    Extension(
        what="Processes on other hosts, over ssh",
        xml='`<machine name="robot2" address="10.0.0.2" user="pi" env-loader="/home/pi/env.sh"'
            '/>`, then `machine="robot2"` on `node` (and its kinds), `executable` or `group`',
        python='`Machine(name="robot2", address="10.0.0.2", …)`, '
               '`GroupAction([PushMachine("robot2"), …])`',
        why="ROS 2 has no multi-host launch. This is roslaunch's "
            "`<machine>` (without `default=`: a group's `machine=` or `PushMachine` scopes "
            "it instead), over the user's own OpenSSH.",
        tags=("machine",),
        attributes=tuple((tag, "machine") for tag in ("executable", "group", "lifecycle_node",
                                                      "node", "node_container"))),
)
