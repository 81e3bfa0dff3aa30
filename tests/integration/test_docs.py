"""The docs site builds strictly (a broken link or anchor fails), its reference pages are
generated from the code and hold every command, tag and type, and the README stays a front
door whose links lead somewhere."""

from __future__ import annotations

import fcntl
import html
import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from launcher.cli.main import COMMANDS
from launcher.control.controllers import TYPES, controller_class
from launcher.control.manager import PARAMETERS as manager_parameters
from launcher.description.registry import Registry
from launcher.nodes.conversions import conversions
from launcher.nodes.foxglove.settings import parameters as foxglove_parameters
from launcher.nodes.joint_state_publisher import PARAMETERS as jsp_parameters
from launcher.nodes.parameter_bridge import PARAMETERS as bridge_parameters
from launcher.nodes.robot_state_publisher import PARAMETERS as rsp_parameters
from launcher.nodes.teleop_twist_keyboard import PARAMETERS as teleop_parameters
from launcher.sim.mujoco_control.ros_plugins import TYPES as PLUGIN_TYPES
from tests.fidelity.choices import CHOICES
from tests.fidelity.corpus import cases
from tests.fidelity.known import KNOWN_DIFFERENCES
from tests.support.environment import REPO


@pytest.fixture(scope="module")
def site(tmp_path_factory) -> Path:
    """The site, built once a session: pytest-xdist's workers share their base folder's
    parent, and the first to come builds it there while the others wait on the lock."""
    shared = tmp_path_factory.getbasetemp()
    if os.environ.get("PYTEST_XDIST_WORKER"):
        shared = shared.parent
    out, built = shared / "docs-site", shared / "docs-site.built"
    with open(shared / "docs-site.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not built.exists():
            build(out)
            built.touch()
    return out


def build(out: Path) -> None:
    env = {**os.environ, "NO_MKDOCS_2_WARNING": "1", "DISABLE_MKDOCS_2_WARNING": "true"}
    done = subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "-d", str(out)],
                          cwd=REPO, env=env, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "WARNING" not in done.stderr, done.stderr


def text(page: Path) -> str:
    """A built page's text, tags dropped and entities read (as a browser shows it)."""
    return html.unescape(re.sub(r"<[^>]+>", "", page.read_text()))


def test_the_cli_reference_has_every_command_and_option(site):
    page = text(site / "reference" / "cli" / "index.html")
    for command in COMMANDS:
        assert f"launcher {command}" in page, command
    for words in ("launcher topic echo", "--qos-reliability", "launcher sim snapshot",
                  "--gui-rate", "launcher gz topic", "--json-output", "launcher rosparam dump"):
        assert words in page, words


def test_the_fidelity_page_gives_the_corpus_counts_and_every_open_difference(site):
    page = text(site / "reference" / "fidelity" / "index.html")
    corpus = cases()
    ros1 = sum(case.flavour == "ros1" for case in corpus)
    assert re.search(rf"ROS 1 \(roslaunch XML\)\s*{ros1}\b", page), page[:2000]
    chosen = [case.name for case in corpus if case.name in CHOICES]
    agree = len(corpus) - len(chosen) - len(KNOWN_DIFFERENCES)
    assert re.search(rf"agree with the real tool\s*{agree}\b", page), page[:2000]
    assert re.search(rf"differ on purpose \(below\)\s*{len(chosen)}\b", page), page[:2000]
    for name in [*KNOWN_DIFFERENCES, *chosen]:
        assert name in page, name
    for name in chosen:  # with its reason (as text: its `code` marks gone)
        assert " ".join(CHOICES[name].reason.replace("`", "").split()[:6]) in page, name


def test_the_launch_file_reference_has_every_tag_substitution_and_field_doc(site):
    page = text(site / "reference" / "launch-files" / "index.html")
    registry = Registry()
    registry.load_all()
    for tag in registry.actions:
        assert tag in page, tag
    for name in registry.substitutions:
        assert f"$({name}" in page, name
    assert "Seconds after SIGINT before SIGTERM." in page  # executable.sigterm_timeout's doc


def test_every_substitution_says_what_it_gives():
    registry = Registry()
    registry.load_all()
    undocumented = sorted(n for n, cls in registry.substitutions.items() if not cls.__doc__)
    assert not undocumented


def test_the_parameters_page_gives_every_controller_and_node_that_declares_them(site):
    page = text(site / "reference" / "parameters" / "index.html")
    declared = {**{t: controller_class(t).PARAMETERS for t in TYPES},
                "foxglove_bridge/foxglove_bridge": foxglove_parameters(),
                "robot_state_publisher/robot_state_publisher": rsp_parameters,
                "joint_state_publisher/joint_state_publisher": jsp_parameters,
                "ros_gz_bridge/parameter_bridge": bridge_parameters,
                "controller_manager/ros2_control_node": manager_parameters,
                "teleop_twist_keyboard/teleop_twist_keyboard": teleop_parameters}
    for name, parameters in declared.items():
        assert name in page, name
        for parameter in parameters:
            assert parameter.name in page and parameter.description in page, parameter
    for name, plugin in PLUGIN_TYPES.items():  # mujoco_ros2_control's, under their prefix
        assert name in page, name
        for parameter in plugin.PARAMETERS:
            assert plugin.scope("{name}") + parameter.name in page, parameter


def test_the_python_api_page_shows_the_documented_node_libraries(site):
    page = text(site / "reference" / "python-apis" / "index.html")
    for module in ("rclpy.node", "rclpy.action.server", "rospy.client", "tf2_ros.buffer",
                   "message_filters", "cv_bridge", "sensor_msgs_py.point_cloud2"):
        assert module in page, module
    assert "create_subscription(msg_type" in page and "A publisher of msg_type on topic" in page


def test_the_type_tables_come_from_the_bridges_own(site):
    page = text(site / "reference" / "types" / "index.html")
    for ros, _ in conversions():
        assert ros in page, ros
    assert "gz.msgs.Pose_V" in page and "ros_gz_interfaces/srv/ControlWorld" in page


def test_the_performance_page_shows_a_recorded_run_as_run_all_printed_it(tmp_path):
    sys.path.insert(0, str(REPO / "docs" / "_gen"))
    try:
        import performance
    finally:
        sys.path.remove(str(REPO / "docs" / "_gen"))
    figures = tmp_path / "figures.json"
    figures.write_text(json.dumps({"date": "2026-11-26", "machine": "2 cores", "commit": "abc",
                                   "rows": [["sim.py", "RTF | paced", "1.00 ± 0.01", "1.000"]]}))
    section = performance.section(figures)
    assert "2 cores, 2026-11-26 (commit `abc`)" in section
    assert "| `sim.py` | RTF \\| paced | 1.00 ± 0.01 | 1.000 |" in section
    assert "No recorded run yet" in performance.section(tmp_path / "none.json")


def test_every_launcher_variable_the_code_reads_is_documented():
    page = (REPO / "docs" / "reference" / "environment.md").read_text()
    found = set()
    for path in (REPO / "launcher").rglob("*.py"):
        found |= set(re.findall(r"\bLAUNCHER_[A-Z][A-Z_]*[A-Z]\b", path.read_text()))
    missing = sorted(name for name in found if name not in page)
    assert not missing, f"not in docs/reference/environment.md: {missing}"


def test_the_readme_is_a_front_door_whose_links_lead_somewhere():
    readme = (REPO / "README.md").read_text()
    assert len(readme.splitlines()) <= 250
    links = re.findall(r"\]\(([^)#]+)(?:#[^)]*)?\)", readme)
    local = [link for link in links if "://" not in link]
    assert local and all((REPO / link).exists() for link in local), \
        [link for link in local if not (REPO / link).exists()]
    assert "sh hooks/bootstrap.sh demo" in readme and "sh hooks/bootstrap.sh test" in readme
