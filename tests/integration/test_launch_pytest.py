"""launch_pytest over launcher: its own examples (../shared/external/launch_testing/launch_pytest)
run unchanged through `pytest` as its README runs them, and the plugin's rules (scopes,
shutdown tests, generators, coroutines, the process tools, the errors), on real processes, each
pytest session on a graph of its own."""

from __future__ import annotations

import subprocess
import sys

import pytest

from tests.support.environment import shared

EXAMPLES = ("launch_testing", "launch_pytest", "test", "launch_pytest", "examples")


def pytest_run(ws, *words: str, cwd=None) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "pytest", "-p", "no:cacheprovider", *words],
                          cwd=cwd or ws.root, env=ws.env, capture_output=True, text=True,
                          timeout=300)


@pytest.mark.parametrize(("name", "passed"), [("pytest_hello_world.py", 1),
                                              ("function_scope.py", 6),
                                              ("module_scope.py", 15),
                                              ("check_node_msgs.py", 1)])
def test_an_example_passes_as_its_readme_runs_it(ws, name, passed):
    example = shared("external", *EXAMPLES, name)
    done = pytest_run(ws, str(example), cwd=example.parents[3])
    assert done.returncode == 0, done.stdout + done.stderr
    assert f"{passed} passed" in done.stdout, done.stdout


def test_the_session_is_not_on_the_users_graph(ws):
    """The talker of check_node_msgs is heard in the session's own run folder, not the user's."""
    example = shared("external", *EXAMPLES, "check_node_msgs.py")
    done = pytest_run(ws, str(example))
    assert done.returncode == 0, done.stdout + done.stderr
    run = ws.root / "run"
    assert not run.exists() or not any(run.iterdir())


HEADER = """
import sys
import launch
import launch_pytest
import pytest
from launch_pytest.tools import process as tools
"""


def write_test(ws, body: str, name: str = "test_it.py"):
    return ws.write(name, HEADER + body)


def test_a_fixture_that_returns_no_description_is_an_error_that_says_so(ws):
    write_test(ws, """
@launch_pytest.fixture
def launch_description():
    return object()

@pytest.mark.launch(fixture=launch_description)
def test_case():
    pass
""")
    done = pytest_run(ws, "test_it.py")
    assert "1 error" in done.stdout, done.stdout
    assert "return value must be either a launch description or a sequence which first item " \
           "is a launch description (it returned object)" in done.stdout


def test_two_ready_to_test_actions_are_an_error(ws):
    write_test(ws, """
@launch_pytest.fixture
def launch_description():
    return launch.LaunchDescription([launch_pytest.actions.ReadyToTest(),
                                     launch_pytest.actions.ReadyToTest()])

@pytest.mark.launch(fixture=launch_description)
def test_case():
    pass
""")
    done = pytest_run(ws, "test_it.py")
    assert "1 error" in done.stdout and "containing only one ReadyToTest action (it has 2)" \
        in done.stdout, done.stdout


def test_a_launch_mark_without_a_fixture_is_skipped_with_the_reason(ws):
    write_test(ws, """
@pytest.mark.launch()
def test_case():
    pass
""")
    done = pytest_run(ws, "test_it.py", "-rs")
    assert "1 skipped" in done.stdout
    assert '"fixture" keyword argument is required in a pytest.mark.launch() decorator' \
        in done.stdout


def test_a_generator_test_marked_shutdown_fails_with_the_reason(ws):
    write_test(ws, """
@launch_pytest.fixture
def launch_description():
    return launch.LaunchDescription([launch_pytest.actions.ReadyToTest()])

@pytest.mark.launch(fixture=launch_description, shutdown=True)
def test_case():
    yield
""")
    done = pytest_run(ws, "test_it.py")
    assert "1 failed" in done.stdout
    assert "generator or async generator based launch test items cannot be marked with " \
           "shutdown=True" in done.stdout


def test_a_generator_that_yields_twice_fails(ws):
    write_test(ws, """
@launch_pytest.fixture
def launch_description():
    return launch.LaunchDescription([launch_pytest.actions.ReadyToTest()])

@pytest.mark.launch(fixture=launch_description)
def test_case():
    yield
    yield
""")
    done = pytest_run(ws, "test_it.py")
    assert "1 failed" in done.stdout
    assert "must stop iteration after yielding once" in done.stdout


def test_the_rest_of_a_generator_whose_first_part_failed_is_skipped(ws):
    write_test(ws, """
@launch_pytest.fixture(scope='module')
def launch_description():
    return launch.LaunchDescription([launch_pytest.actions.ReadyToTest()])

@pytest.mark.launch(fixture=launch_description)
async def test_case():
    assert False
    yield
""")
    done = pytest_run(ws, "test_it.py")
    assert "1 failed, 1 skipped" in done.stdout, done.stdout


PROCESS = """
SCRIPT = "import sys, time\\nprint('hello')\\nprint('world', file=sys.stderr)\\ntime.sleep(30)"

@pytest.fixture
def dut():
    return launch.actions.ExecuteProcess(cmd=[sys.executable, '-c', SCRIPT],
                                         cached_output=True, output='screen')

@launch_pytest.fixture
def launch_description(dut):
    return launch.LaunchDescription([dut, launch_pytest.actions.ReadyToTest()])
"""


def test_the_sync_process_tools_see_start_output_and_exit(ws):
    write_test(ws, PROCESS + """
@pytest.mark.launch(fixture=launch_description)
def test_case(dut, launch_context, launch_service):
    assert tools.wait_for_start_sync(launch_context, dut, timeout=10)
    tools.assert_output_sync(launch_context, dut, lambda out: out.splitlines() == ['hello'],
                             timeout=10)
    tools.assert_stderr_sync(launch_context, dut, lambda err: err.splitlines() == ['world'],
                             timeout=10)
    assert not tools.wait_for_output_sync(launch_context, dut, lambda out: 'never' in out,
                                          timeout=0.2)
    assert dut.return_code is None
    launch_service.shutdown()
    assert tools.wait_for_exit_sync(launch_context, dut, timeout=10)
    assert dut.return_code == -2
""")
    done = pytest_run(ws, "test_it.py")
    assert done.returncode == 0, done.stdout + done.stderr


def test_the_async_process_tools_run_beside_the_tests_loop(ws):
    write_test(ws, PROCESS + """
@pytest.mark.launch(fixture=launch_description)
async def test_case(dut, launch_context):
    assert await tools.wait_for_start(launch_context, dut, timeout=10)
    await tools.assert_output(launch_context, dut, lambda out: out.splitlines() == ['hello'],
                              timeout=10)
    assert await tools.wait_for_stderr(launch_context, dut, lambda err: 'world' in err,
                                       timeout=10)
    assert not await tools.wait_for_exit(launch_context, dut, timeout=0.2)
""")
    done = pytest_run(ws, "test_it.py")
    assert done.returncode == 0, done.stdout + done.stderr


def test_a_start_that_came_before_the_wait_counts(ws):
    """launch_pytest's tools wait for the next event; a process already started or exited is
    not waited for again here."""
    write_test(ws, """
@pytest.fixture
def dut():
    return launch.actions.ExecuteProcess(cmd=['true'])

@launch_pytest.fixture
def launch_description(dut):
    return launch.LaunchDescription([dut, launch_pytest.actions.ReadyToTest()])

@pytest.mark.launch(fixture=launch_description)
def test_case(dut, launch_context):
    assert tools.wait_for_exit_sync(launch_context, dut, timeout=10)
    assert tools.wait_for_start_sync(launch_context, dut, timeout=0)
    assert dut.return_code == 0
""")
    done = pytest_run(ws, "test_it.py")
    assert done.returncode == 0, done.stdout + done.stderr


def test_a_launch_whose_action_fails_fails_the_test_and_leaves_nothing_running(ws):
    write_test(ws, """
@launch_pytest.fixture
def launch_description():
    return launch.LaunchDescription([
        launch.actions.ExecuteProcess(cmd=['sleep', '30']),
        launch.actions.ExecuteProcess(cmd=['no-such-program-here']),
        launch_pytest.actions.ReadyToTest()])

@pytest.mark.launch(fixture=launch_description)
def test_case():
    pass
""")
    done = pytest_run(ws, "test_it.py")
    assert done.returncode == 1
    assert "executable 'no-such-program-here' not found on PATH" in done.stdout + done.stderr
    assert "launch service failed when finishing" in done.stdout


def test_a_ready_to_test_that_never_comes_fails_at_the_configured_time(ws):
    write_test(ws, """
@launch_pytest.fixture
def launch_description():
    return launch.LaunchDescription([
        launch.actions.ExecuteProcess(cmd=['sleep', '30']),
        launch.actions.TimerAction(period=60.0,
                                   actions=[launch_pytest.actions.ReadyToTest()])])

@pytest.mark.launch(fixture=launch_description)
def test_case():
    pass
""")
    done = pytest_run(ws, "test_it.py", "-o", "launch_pytest_ready_timeout=1")
    assert "1 error" in done.stdout
    assert "ReadyToTest was never reached: it was not reached in 1 s " \
           "(launch_pytest_ready_timeout in the pytest configuration)" in done.stdout


TALKER = """
import rclpy
from rclpy.node import Node
from std_msgs.msg import String

WORD = {word!r}
TALKER = "import rclpy, sys\\nfrom std_msgs.msg import String\\nrclpy.init()\\n" \\
    "node = rclpy.create_node('talker')\\npub = node.create_publisher(String, 'chatter', 10)\\n" \\
    "node.create_timer(0.05, lambda: pub.publish(String(data=sys.argv[1])))\\nrclpy.spin(node)"

@launch_pytest.fixture
def launch_description():
    return launch.LaunchDescription([
        launch.actions.ExecuteProcess(cmd=[sys.executable, '-c', TALKER, WORD]),
        launch_pytest.actions.ReadyToTest()])

@pytest.mark.launch(fixture=launch_description)
def test_only_its_own_talker_is_heard():
    heard = set()
    rclpy.init()
    node = rclpy.create_node('listener')
    node.create_subscription(String, 'chatter', lambda m: heard.add(m.data), 10)
    deadline = __import__('time').monotonic() + 4
    while __import__('time').monotonic() < deadline:
        rclpy.spin_once(node, timeout_sec=0.1)
    node.destroy_node()
    rclpy.shutdown()
    assert heard == {{WORD}}
"""


def test_sessions_in_parallel_each_hear_only_their_own_launch(ws):
    """`pytest -n 2`: each worker is a session with a graph of its own, so two launches that
    publish on the same topic at the same time do not hear each other."""
    for word in ("alpha", "beta", "gamma", "delta"):
        write_test(ws, TALKER.format(word=word), name=f"test_{word}.py")
    done = pytest_run(ws, "-n", "2", "test_alpha.py", "test_beta.py", "test_gamma.py",
                      "test_delta.py")
    assert done.returncode == 0, done.stdout + done.stderr
    assert "4 passed" in done.stdout


def test_an_output_check_that_returns_false_fails_with_the_output(ws):
    """launch_pytest's assert_output_sync lets a validator that returns False pass; here it
    fails, saying what the output was."""
    write_test(ws, PROCESS + """
@pytest.mark.launch(fixture=launch_description)
def test_case(dut, launch_context):
    tools.assert_output_sync(launch_context, dut, lambda out: 'goodbye' in out, timeout=0.5)
""")
    done = pytest_run(ws, "test_it.py")
    assert "1 failed" in done.stdout, done.stdout
    assert "the stdout of python-1 did not pass <lambda> within 0.5 s; it was:" in done.stdout
