"""launch_testing's own example tests (../shared/external/launch_testing), run unchanged as its
README runs them, through `launcher test` (the shell's `launch_test`, `ros2 test`, `python -m
launch_testing.launch_test`): each gives the result its authors intended, on real processes."""

from __future__ import annotations

import os
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from tests.support.environment import shared

EXAMPLES = ("launch_testing", "launch_testing", "test", "launch_testing", "examples")


@pytest.fixture
def examples(ws) -> Path:
    """The examples, and an install prefix of `launch_testing` whose lib/launch_testing holds
    the example processes they start (links to the shared files, as its install has them)."""
    processes = shared("external", "launch_testing", "launch_testing", "example_processes")
    prefix = ws.root / "prefix"
    (prefix / "share" / "ament_index" / "resource_index" / "packages").mkdir(parents=True)
    (prefix / "share" / "ament_index" / "resource_index" / "packages" / "launch_testing").touch()
    (prefix / "lib" / "launch_testing").mkdir(parents=True)
    for script in processes.glob("*.py"):
        (prefix / "lib" / "launch_testing" / script.name).symlink_to(script)
    ws.env["AMENT_PREFIX_PATH"] = str(prefix)
    return shared("external", *EXAMPLES)


def run_test(ws, path: Path, *words: str) -> subprocess.CompletedProcess:
    return ws.run("test", str(path), *words, timeout=120)


PASSING = ["hello_world_launch_test.py", "good_proc_launch_test.py",
           "terminating_proc_launch_test.py", "context_launch_test.py",
           "parameters_launch_test.py", "ready_action_test.py"]


@pytest.mark.parametrize("name", PASSING)
def test_an_example_passes(ws, examples, name):
    done = run_test(ws, examples / name)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "FAILED" not in done.stderr and "\nOK" in done.stderr


def test_the_ready_to_test_timeout_example_waits_past_the_default_fifteen_seconds(ws, examples):
    done = run_test(ws, examples / "ready_to_test_action_timeout_test.py")
    assert done.returncode == 0, done.stdout + done.stderr


def test_the_args_example_passes_with_its_argument(ws, examples):
    done = run_test(ws, examples / "args_launch_test.py", "dut_arg:=hey")
    assert done.returncode == 0, done.stdout + done.stderr


def test_the_args_example_fails_without_its_argument_as_its_readme_says(ws, examples):
    done = run_test(ws, examples / "args_launch_test.py")
    assert done.returncode == 1
    assert "FAIL: test_ran_with_arg" in done.stderr and \
        "Try running: launch_test test_with_args.test.py dut_arg:=arg" in done.stderr


def test_show_args_lists_the_tests_launch_arguments(ws, examples):
    done = run_test(ws, examples / "args_launch_test.py", "--show-args")
    assert done.returncode == 0, done.stderr
    assert "'dut_arg':\n        Passed to the terminating process\n        (default: 'default')" \
        in done.stdout


def test_a_parametrized_description_runs_once_per_value(ws, examples):
    done = run_test(ws, examples / "parameters_launch_test.py")
    assert done.stderr.count("Starting test run") == 3
    assert "test_process_outputs_expected_value[thing=Off]" in done.stderr


def test_junit_xml_holds_every_test_and_its_outcome(ws, examples):
    report = ws.root / "results" / "good_proc.xml"
    done = run_test(ws, examples / "good_proc_launch_test.py", "--junit-xml", str(report))
    assert done.returncode == 0, done.stderr
    suite = ET.parse(report).getroot().find("testsuite")
    names = {case.get("name") for case in suite.iter("testcase")}
    assert suite.get("tests") == "4" and suite.get("failures") == "0"
    assert {"test_count_to_four", "test_exit_code", "test_full_output",
            "test_out_of_order"} == names


def test_launch_test_on_the_shells_path_is_launchers(ws, examples):
    from launcher import compat

    ws.env["PATH"] = f"{Path(sys.executable).parent}:{ws.env['PATH']}:{compat.COMMANDS}"
    done = subprocess.run(["launch_test", str(examples / "hello_world_launch_test.py")],
                          cwd=ws.root, env=ws.env, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stdout + done.stderr


def test_ros2_test_runs_a_launch_test(ws, examples):
    done = ws.run("ros2", "test", str(examples / "hello_world_launch_test.py"), timeout=120)
    assert done.returncode == 0, done.stdout + done.stderr


def test_python_m_launch_testing_launch_test_runs_it(ws, examples):
    from launcher import compat

    ws.env["PYTHONPATH"] = os.pathsep.join(filter(None, [ws.env.get("PYTHONPATH"),
                                                         compat.SHIMS]))
    done = subprocess.run([sys.executable, "-m", "launch_testing.launch_test",
                           str(examples / "hello_world_launch_test.py")], cwd=ws.root,
                          env=ws.env, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stdout + done.stderr


EXPECTED_OUTPUT_TEST = """
import os
import sys
import unittest

import launch
import launch_testing
import launch_testing.actions
import launch_testing.tools
import launch_testing_ros.tools

HERE = os.path.dirname(__file__)
# (it goes on, as a node does: one that ended before the test finished would fail the run, as
# launch_testing says "Processes under test stopped before tests completed")
TALK = ("import time; print('pid 42'); print('hello 1'); print('noise'); "
        "print('hello 2', flush=True); time.sleep(60)")


def generate_test_description():
    talker = launch.actions.ExecuteProcess(cmd=[sys.executable, "-c", TALK], output="screen")
    return launch.LaunchDescription([talker, launch_testing.actions.ReadyToTest()]), \
        {"talker": talker}


class TestTalkerOutput(unittest.TestCase):
    def test_the_talker_says_what_the_file_expects(self, proc_output, talker):
        output_filter = launch_testing_ros.tools.basic_output_filter(
            filtered_rmw_implementation="rmw_zenoh_cpp")
        proc_output.assertWaitFor(
            expected_output=launch_testing.tools.expected_output_from_file(
                path=os.path.join(HERE, "talker")),
            process=talker, output_filter=output_filter, timeout=10, stream="stdout")
"""


def test_expected_output_from_a_file_through_the_ros_output_filter(ws):
    """ROS 2's demo packages check their nodes so: launch_testing.tools and
    launch_testing_ros.tools, the expected lines in a .regex file."""
    ws.write("talker.regex", "hello \\d\nhello 2\n")
    path = ws.write("talker_test.py", EXPECTED_OUTPUT_TEST)
    done = run_test(ws, path)
    assert done.returncode == 0, done.stdout + done.stderr


# --- bad inputs ---------------------------------------------------------------------------------
def test_a_file_without_generate_test_description_is_said_by_name(ws):
    path = ws.write("empty_test.py", "import unittest\n")
    done = run_test(ws, path)
    assert done.returncode == 1
    assert done.stderr.strip() == (f"error: {path}: a launch test file must define "
                                   "generate_test_description()")


def test_a_description_without_ready_to_test_fails_with_the_reason(ws):
    path = ws.write("no_ready_test.py", """
        import launch

        def generate_test_description():
            return launch.LaunchDescription([])
        """)
    done = run_test(ws, path)
    assert done.returncode == 1
    assert done.stderr.strip() == (f"error: {path}:3: generate_test_description functions must "
                                   "return a LaunchDescription containing a ReadyToTest action")


def test_a_ready_to_test_that_never_comes_fails_after_its_timeout(ws):
    path = ws.write("late_test.py", """
        import unittest
        import launch
        import launch_testing
        import launch_testing.actions
        import launch_testing.util

        @launch_testing.ready_to_test_action_timeout(1)
        def generate_test_description():
            return launch.LaunchDescription([
                launch_testing.util.KeepAliveProc(),
                launch.actions.TimerAction(period=30.0,
                                           actions=[launch_testing.actions.ReadyToTest()]),
            ])

        class TestNever(unittest.TestCase):
            def test_never_runs(self):
                pass
        """)
    done = run_test(ws, path)
    assert done.returncode == 1
    assert "Timed out waiting for processes to start up: ReadyToTest was not reached in 1 s" \
        in done.stderr


def test_a_test_file_that_fails_to_import_is_said_at_its_line(ws):
    path = ws.write("broken_test.py", "import launch\nraise ValueError('no')\n")
    done = run_test(ws, path)
    assert done.returncode == 1
    assert done.stderr.startswith(f"error: {path}:2: the test file raised ValueError: no")


def test_a_missing_test_file_is_said(ws):
    done = run_test(ws, ws.root / "nope_test.py")
    assert done.returncode == 2 and "does not exist" in done.stderr


def test_the_launch_is_not_on_the_users_graph(ws, examples):
    """Its run folder is its own: nothing of the test's is in the user's run folder."""
    run = ws.root / "run"
    done = run_test(ws, examples / "hello_world_launch_test.py")
    assert done.returncode == 0, done.stderr
    assert not run.exists() or not any(run.iterdir())


# --- through pytest (launch_testing's pytest plugin: how colcon test runs them) ---------------
def pytest_run(ws, *words: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "pytest", "-p", "no:cacheprovider", *words],
                          cwd=ws.root, env=ws.env, capture_output=True, text=True, timeout=300)


def test_pytest_runs_a_launch_test_file_as_one_passing_item(ws, examples):
    done = pytest_run(ws, str(examples / "good_proc_launch_test.py"))
    assert done.returncode == 0, done.stdout + done.stderr
    assert "1 passed" in done.stdout


def test_pytest_fails_a_launch_test_with_the_failing_tests_reports(ws, examples):
    done = pytest_run(ws, str(examples / "args_launch_test.py"))
    assert done.returncode == 1
    assert "FAIL: args_launch_test.args_launch_test.TestProcessOutput.test_ran_with_arg" \
        in done.stdout


def test_pytest_gives_launch_args_to_a_launch_test(ws, examples):
    done = pytest_run(ws, str(examples / "args_launch_test.py"), "--launch-args", "dut_arg:=hey")
    assert done.returncode == 0, done.stdout + done.stderr


def test_pytest_leaves_a_file_without_the_launch_test_mark_to_itself(ws):
    path = ws.write("test_plain.py", """
        def generate_test_description():
            return None

        def test_plain():
            assert generate_test_description() is None
        """)
    done = pytest_run(ws, str(path))
    assert done.returncode == 0 and "1 passed" in done.stdout, done.stdout


def test_pytest_runs_a_file_marked_rostest_as_launch_testing_ros_has_it(ws):
    path = ws.write("test_marked_rostest.py", """
        import unittest
        import launch
        import launch_testing.actions
        import pytest

        @pytest.mark.rostest
        def generate_test_description():
            return launch.LaunchDescription([
                launch.actions.ExecuteProcess(cmd=["echo", "ros"]),
                launch_testing.actions.ReadyToTest()])

        class TestEcho(unittest.TestCase):
            def test_echo(self, proc_output):
                proc_output.assertWaitFor("ros", stream="stdout", timeout=5)
        """)
    done = pytest_run(ws, str(path))
    assert done.returncode == 0, done.stdout + done.stderr
    assert "1 passed" in done.stdout  # (as a plain module: 'fixture proc_output not found')


# --- launch_testing_ros and controller_manager.test_utils --------------------------------------
TALKER = """
import rclpy
from std_msgs.msg import String

rclpy.init()
node = rclpy.create_node("talker")
publisher = node.create_publisher(String, "chatter", 10)
node.create_timer(0.1, lambda: publisher.publish(String(data="hello")))
try:
    rclpy.spin(node)
except KeyboardInterrupt:
    pass
"""

ROS_TEST = """
import sys
import unittest

import launch
import launch_testing
import launch_testing.actions
import pytest
import rclpy
from controller_manager.test_utils import check_node_running
from launch_testing_ros import WaitForTopics
from std_msgs.msg import String


@pytest.mark.launch_test
def generate_test_description():
    return launch.LaunchDescription([
        launch.actions.ExecuteProcess(cmd=[sys.executable, "{talker}"]),
        launch_testing.actions.ReadyToTest(),
    ])


class TestTalker(unittest.TestCase):
    def test_chatter_carries_hello(self):
        with WaitForTopics([("chatter", String)], timeout={timeout}) as waited:
            self.assertEqual(waited.received_messages("chatter")[0].data, "hello")

    def test_the_talker_is_on_the_graph(self):
        rclpy.init()
        node = rclpy.create_node("checker")
        try:
            check_node_running(node, "talker", timeout=10.0)
        finally:
            node.destroy_node()
            rclpy.shutdown()
"""


def test_wait_for_topics_hears_a_nodes_messages_on_the_tests_graph(ws):
    talker = ws.write("talker.py", TALKER)
    path = ws.write("ros_launch_test.py", ROS_TEST.format(talker=talker, timeout=10.0))
    done = run_test(ws, path)
    assert done.returncode == 0, done.stdout + done.stderr


def test_wait_for_topics_fails_when_a_topic_stays_silent(ws):
    talker = ws.write("talker.py", "import time\ntime.sleep(60)\n")
    path = ws.write("ros_launch_test.py", ROS_TEST.format(talker=talker, timeout=1.0))
    done = run_test(ws, path)
    assert done.returncode == 1
    assert "RuntimeError: ('Did not receive messages on these topics: ', {'chatter'})" \
        in done.stderr


CONTROL_TEST = """
import os
import unittest

import launch
import launch_testing.actions
import pytest
import rclpy
from ament_index_python.packages import get_package_share_directory
from controller_manager.test_utils import check_controllers_running, check_if_js_published
from launch.launch_description_sources import PythonLaunchDescriptionSource


@pytest.mark.launch_test
def generate_test_description():
    demo = os.path.join(get_package_share_directory("gz_ros2_control_demos"), "launch",
                        "cart_example_position.launch.py")
    return launch.LaunchDescription([
        launch.actions.IncludeLaunchDescription(PythonLaunchDescriptionSource(demo)),
        launch_testing.actions.ReadyToTest(),
    ])


class TestControllers(unittest.TestCase):
    def test_the_cart_is_controlled(self):
        rclpy.init()
        node = rclpy.create_node("controller_checker")
        try:
            check_controllers_running(node, [{names}])
            check_if_js_published("/joint_states", ["slider_to_cart"])
        finally:
            node.destroy_node()
            rclpy.shutdown()
"""


def test_controller_manager_test_utils_check_a_ros2_control_demo(ws):
    ws.own_bus().env["LAUNCHER_PACKAGE_PATH"] = str(shared("external", "gz_ros2_control_demos"))
    names = '"joint_trajectory_controller", "joint_state_broadcaster"'
    path = ws.write("control_launch_test.py", CONTROL_TEST.replace("{names}", names))
    done = run_test(ws, path)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]


def test_controller_manager_test_utils_say_which_controller_is_missing(ws):
    ws.own_bus().env["LAUNCHER_PACKAGE_PATH"] = str(shared("external", "gz_ros2_control_demos"))
    path = ws.write("control_launch_test.py",
                    CONTROL_TEST.replace("{names}", '"no_such_controller"'))
    done = run_test(ws, path)
    assert done.returncode == 1
    assert "Controller node(s) not found: ns: /, ctrl:no_such_controller" in done.stderr


# --- colcon test: an ament_python package's pytest tests and launch tests ----------------------
PACKAGE = {
    "src/talk_pkg/package.xml": """<?xml version="1.0"?>
<package format="3">
  <name>talk_pkg</name>
  <version>0.0.1</version>
  <description>talks</description>
  <maintainer email="dev@example.com">dev</maintainer>
  <license>Apache-2.0</license>
  <test_depend>launch_testing</test_depend>
  <export><build_type>ament_python</build_type></export>
</package>
""",
    "src/talk_pkg/setup.py": """from setuptools import setup
setup(name="talk_pkg", version="0.0.1", packages=["talk_pkg"], tests_require=["pytest"],
      data_files=[("share/ament_index/resource_index/packages", ["resource/talk_pkg"]),
                  ("share/talk_pkg", ["package.xml"])])
""",
    "src/talk_pkg/resource/talk_pkg": "",
    "src/talk_pkg/talk_pkg/__init__.py": "",
    "src/talk_pkg/test/test_unit.py": "def test_adds():\n    assert 1 + 1 == 2\n",
    "src/talk_pkg/test/test_echo_launch.py": """import unittest

import launch
import launch_testing.actions
import launch_testing.util
import pytest


@pytest.mark.launch_test
def generate_test_description():
    return launch.LaunchDescription([
        launch.actions.ExecuteProcess(cmd=["echo", "{said}"]),
        launch_testing.util.KeepAliveProc(),
        launch_testing.actions.ReadyToTest(),
    ])


class TestEcho(unittest.TestCase):
    def test_says_hi(self, proc_output):
        proc_output.assertWaitFor("hi there", stream="stdout", timeout=3)
""",
    "src/talk_pkg/test/test_echo_pytest.py": """import launch
import launch_pytest
from launch_pytest.tools import process as process_tools
import pytest


@pytest.fixture
def echo():
    return launch.actions.ExecuteProcess(cmd=["echo", "{said}"], cached_output=True)


@launch_pytest.fixture
def launch_description(echo):
    return launch.LaunchDescription([echo, launch_pytest.actions.ReadyToTest()])


@pytest.mark.launch(fixture=launch_description)
def test_says_hi(echo, launch_context):
    process_tools.assert_output_sync(launch_context, echo,
                                     lambda out: out.strip() == "hi there", timeout=5)
""",
}


def colcon_tested(ws, files: dict[str, str], said: str) -> subprocess.CompletedProcess:
    """The workspace of `files` built and tested: what `colcon test-result --verbose` says."""
    for name, text in files.items():
        path = ws.root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text.replace("{said}", said))
    built = ws.run("colcon", "build", timeout=300)
    assert built.returncode == 0, built.stdout + built.stderr
    ws.run("colcon", "test", timeout=300)
    return ws.run("colcon", "test-result", "--verbose", timeout=60)


def test_colcon_test_runs_a_packages_pytest_launch_and_launch_pytest_tests(ws):
    result = colcon_tested(ws, PACKAGE, "hi there")
    assert result.returncode == 0, result.stdout
    assert "3 tests, 0 errors, 0 failures, 0 skipped" in result.stdout


def test_colcon_test_result_names_failing_launch_tests(ws):
    result = colcon_tested(ws, PACKAGE, "bye")
    assert result.returncode == 1
    assert "3 tests, 0 errors, 2 failures, 0 skipped" in result.stdout
    assert "test_echo_launch" in result.stdout and "test_echo_pytest" in result.stdout


OWN_WORD_TEST = """import sys
import time
import unittest

import launch
import launch_testing.actions
import pytest
import rclpy
from std_msgs.msg import String

TALK = ("import rclpy, sys\\nfrom std_msgs.msg import String\\nrclpy.init()\\n"
        "node = rclpy.create_node('talker')\\n"
        "pub = node.create_publisher(String, 'chatter', 10)\\n"
        "node.create_timer(0.05, lambda: pub.publish(String(data=sys.argv[1])))\\n"
        "rclpy.spin(node)")


@pytest.mark.launch_test
def generate_test_description():
    return launch.LaunchDescription([
        launch.actions.ExecuteProcess(cmd=[sys.executable, "-c", TALK, "{word}"]),
        launch_testing.actions.ReadyToTest()])


class TestOwnWord(unittest.TestCase):
    def test_only_its_own_talker_is_heard(self):
        heard = set()
        rclpy.init()
        node = rclpy.create_node("listener")
        node.create_subscription(String, "chatter", lambda m: heard.add(m.data), 10)
        end = time.monotonic() + 4
        while time.monotonic() < end:
            rclpy.spin_once(node, timeout_sec=0.1)
        rclpy.shutdown()
        self.assertEqual(heard, {{"{word}"}})
"""


def word_package(name: str, word: str) -> dict[str, str]:
    return {
        f"src/{name}/package.xml": PACKAGE["src/talk_pkg/package.xml"].replace("talk_pkg", name),
        f"src/{name}/setup.py": PACKAGE["src/talk_pkg/setup.py"].replace("talk_pkg", name),
        f"src/{name}/resource/{name}": "",
        f"src/{name}/{name}/__init__.py": "",
        f"src/{name}/test/test_own_word_launch.py": OWN_WORD_TEST.format(word=word),
    }


def test_colcon_test_runs_packages_in_parallel_each_on_a_graph_of_its_own(ws):
    """Two packages' launch tests publish on the same topic at the same time, and each hears
    only its own (with no ROS_DOMAIN_ID set)."""
    for name, text in {**word_package("pkg_a", "alpha"), **word_package("pkg_b", "beta")}.items():
        path = ws.root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    built = ws.run("colcon", "build", timeout=300)
    assert built.returncode == 0, built.stdout + built.stderr
    ws.run("colcon", "test", "--parallel-workers", "2", timeout=300)
    result = ws.run("colcon", "test-result", "--verbose", timeout=60)
    assert result.returncode == 0, result.stdout
    assert "2 tests, 0 errors, 0 failures, 0 skipped" in result.stdout


def test_a_hanging_test_fails_at_the_time_limit_and_leaves_nothing_running(ws):
    path = ws.write("hang_test.py", """
        import time
        import unittest
        import launch
        import launch_testing.actions
        import launch_testing.util

        def generate_test_description():
            return launch.LaunchDescription([
                launch_testing.util.KeepAliveProc(), launch_testing.actions.ReadyToTest()])

        class TestHang(unittest.TestCase):
            def test_forever(self):
                time.sleep(3600)
        """)
    done = run_test(ws, path, "--timeout", "2")
    assert done.returncode == 1
    assert "FAIL: hang_test.hang_test.launch_tests: the active tests did not finish within 2 s" \
        in done.stderr


CMAKE_PACKAGE = {
    "src/cm_pkg/package.xml": """<?xml version="1.0"?>
<package format="3">
  <name>cm_pkg</name>
  <version>0.0.1</version>
  <description>cmake tests</description>
  <maintainer email="dev@example.com">dev</maintainer>
  <license>Apache-2.0</license>
  <buildtool_depend>ament_cmake</buildtool_depend>
  <test_depend>launch_testing_ament_cmake</test_depend>
  <test_depend>ament_cmake_pytest</test_depend>
  <export><build_type>ament_cmake</build_type></export>
</package>
""",
    "src/cm_pkg/CMakeLists.txt": """cmake_minimum_required(VERSION 3.8)
project(cm_pkg)
find_package(ament_cmake REQUIRED)
if(BUILD_TESTING)
  find_package(launch_testing_ament_cmake REQUIRED)
  find_package(ament_cmake_pytest REQUIRED)
  add_launch_test(test/test_echo_launch.py TIMEOUT 30)
  ament_add_pytest_test(test_unit test/test_unit.py)
endif()
ament_package()
""",
    "src/cm_pkg/test/test_unit.py": PACKAGE["src/talk_pkg/test/test_unit.py"],
    "src/cm_pkg/test/test_echo_launch.py": PACKAGE["src/talk_pkg/test/test_echo_launch.py"],
}


def test_colcon_test_runs_add_launch_test_and_ament_add_pytest_test(ws):
    result = colcon_tested(ws, CMAKE_PACKAGE, "hi there")
    assert result.returncode == 0, result.stdout
    # (each test twice, as on ROS: ctest's record and the test's own JUnit results)
    assert "4 tests, 0 errors, 0 failures, 0 skipped" in result.stdout


def test_colcon_test_result_names_a_failing_add_launch_test(ws):
    result = colcon_tested(ws, CMAKE_PACKAGE, "bye")
    assert result.returncode == 1
    assert "test_echo_launch" in result.stdout and "0 errors, 2 failures" in result.stdout
