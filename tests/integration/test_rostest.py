"""rostest over launcher: a ROS 1 package's .test file, its nodes launched and its `<test>`s
run against them (rospy tests through rostest.rosrun), rostest's summary and results, the
bad inputs; and roslaunch leaving the tests out. Real processes on a graph of the test's."""

from __future__ import annotations

import signal
import time
import xml.etree.ElementTree as ET

import pytest

from tests.support.hear_pkg import make_package, write_test


@pytest.fixture
def package(ws):
    """A ROS 1 package with a talker and a rospy test of it; results under the ws."""
    root = make_package(ws.root / "src")
    ws.own_bus().env.update(LAUNCHER_PACKAGE_PATH=str(ws.root / "src"),
                            ROS_HOME=str(ws.root / "home"))
    return root


def results(ws):
    return ws.root / "home" / "test_results" / "hear_pkg"


def test_a_test_that_hears_its_node_passes_with_rostests_summary(ws, package):
    write_test(package)
    done = ws.run("rostest", "hear_pkg", "hear.test", timeout=120)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "[hear.rosunit-hear_test][passed]" in done.stdout
    assert "SUMMARY\n * RESULT: SUCCESS\n * TESTS: 1\n * ERRORS: 0\n * FAILURES: 0" \
        in done.stdout


def test_the_results_are_written_where_rostest_writes_them(ws, package):
    write_test(package)
    ws.run("rostest", "hear_pkg", "hear.test", timeout=120)
    case = ET.parse(results(ws) / "rosunit-hear_test.xml").getroot().find(".//testcase")
    assert case.get("name") == "test_hears_hello"
    summary = ET.parse(results(ws) / "rostest-hear.xml").getroot()
    assert (summary.get("tests"), summary.get("failures")) == ("1", "0")


def test_a_failing_test_fails_the_run_and_says_its_case(ws, package):
    write_test(package, expected="bye")
    done = ws.run("rostest", "hear_pkg", "hear.test", timeout=120)
    assert done.returncode == 1
    assert "[hear.rosunit-hear_test][FAILURE]" in done.stdout
    assert "test_hears_bye: AssertionError: 'hello' != 'bye'" in done.stdout
    assert " * RESULT: FAIL" in done.stdout


def test_a_test_past_its_time_limit_is_stopped_and_fails(ws, package):
    write_test(package, delay=60, limit=2)
    done = ws.run("rostest", "hear_pkg", "hear.test", timeout=120)
    assert done.returncode == 1
    assert "test [hear_test] ran past its time limit of 2 s and was stopped" in done.stdout


def test_a_failed_test_is_run_again_while_retries_are_left(ws, package):
    write_test(package, expected="bye", extra='retry="1"')
    done = ws.run("rostest", "hear_pkg", "hear.test", timeout=120)
    assert done.returncode == 1
    log = next((ws.root / "log").rglob("launch.log")).read_text()
    assert log.count("test_hears_bye (__main__.TestHear.test_hears_bye) ... FAIL") == 2


def test_a_test_file_by_path_runs_too(ws, package):
    write_test(package)
    done = ws.run("rostest", str(package / "test" / "hear.test"), timeout=120)
    assert done.returncode == 0, done.stdout + done.stderr


def test_roslaunch_leaves_the_tests_out(ws, package):
    write_test(package)
    done = ws.run("roslaunch", "hear_pkg", "hear.test", "--nodes", timeout=60)
    assert done.returncode == 0, done.stderr
    assert done.stdout.split() == ["/talker"]


# --- bad inputs ---------------------------------------------------------------------------------
def test_an_unknown_test_attribute_is_warned_at_its_place_and_left_out_as_roslaunch_does(
        ws, package):
    write_test(package, extra='time-limt="3"')
    done = ws.run("rostest", "hear_pkg", "hear.test", timeout=60)
    assert done.returncode == 0, done.stdout + done.stderr
    said = done.stdout + done.stderr
    assert f"{package / 'test' / 'hear.test'}:3:" in said
    assert "has no attribute 'time-limt' (did you mean 'time-limit'?)" in said


def test_a_test_whose_type_is_not_found_is_said(ws, package):
    write_test(package, type_="nope_test.py")
    done = ws.run("rostest", "hear_pkg", "hear.test", timeout=60)
    assert done.returncode == 1
    assert "nope_test.py" in done.stdout + done.stderr


def test_a_file_without_tests_is_said(ws, package):
    (package / "test" / "empty.test").write_text(
        '<launch><node pkg="hear_pkg" type="talker.py" name="talker" /></launch>\n')
    done = ws.run("rostest", "hear_pkg", "empty.test", timeout=60)
    assert done.returncode == 1
    assert "the file has no <test>: nothing to run" in done.stderr


# --- catkin_make run_tests and catkin_test_results ------------------------------------------------
CMAKE = """cmake_minimum_required(VERSION 3.0.2)
project(hear_pkg)
find_package(catkin REQUIRED COMPONENTS rospy rostest)
catkin_package()
if(CATKIN_ENABLE_TESTING)
  add_rostest(test/hear.test)
endif()
"""


def test_catkin_make_run_tests_runs_each_add_rostest_and_catkin_test_results_sums_them(
        ws, package):
    write_test(package)
    (package / "CMakeLists.txt").write_text(CMAKE)
    made = ws.run("catkin_make", "run_tests", timeout=180)
    assert made.returncode == 0, made.stdout + made.stderr
    assert (ws.root / "build" / "test_results" / "hear_pkg" / "rostest-hear.xml").is_file()
    summed = ws.run("catkin_test_results", "build/test_results", timeout=60)
    assert summed.returncode == 0, summed.stdout + summed.stderr
    assert "Summary: 1 tests, 0 errors, 0 failures, 0 skipped" in summed.stdout


def test_catkin_test_results_fails_and_names_a_failing_test(ws, package):
    write_test(package, expected="bye")
    (package / "CMakeLists.txt").write_text(CMAKE)
    made = ws.run("catkin_make", "run_tests", timeout=180)
    assert made.returncode == 0, made.stdout + made.stderr  # (as catkin's run_tests target)
    summed = ws.run("catkin_test_results", "build/test_results", "--verbose", timeout=60)
    assert summed.returncode == 1
    assert "hear.rosunit.hear_test" in summed.stdout
    assert "Summary: 1 tests, 0 errors, 1 failures, 0 skipped" in summed.stdout


def test_catkin_test_results_without_results_is_said(ws):
    done = ws.run("catkin_test_results", "build/test_results", timeout=60)
    assert done.returncode == 2 and "does not exist" in done.stderr


# --- rostest's hztest ---------------------------------------------------------------------------
HZ_TEST = """<launch>
  <node pkg="hear_pkg" type="talker.py" name="talker" />
  <test test-name="hz" pkg="rostest" type="hztest" time-limit="30">
    <param name="topic" value="chatter" />
    <param name="hz" value="{hz}" />
    <param name="hzerror" value="2.0" />
    <param name="test_duration" value="2.0" />
  </test>
</launch>
"""


@pytest.mark.parametrize(("hz", "code"), [("10.0", 0), ("50.0", 1)], ids=["right", "wrong"])
def test_hztest_checks_a_topics_rate(ws, package, hz, code):
    (package / "test" / "hz.test").write_text(HZ_TEST.format(hz=hz))
    done = ws.run("rostest", "hear_pkg", "hz.test", timeout=120)
    assert done.returncode == code, done.stdout + done.stderr
    if code:
        assert "Hz, expected 50 ± 2 Hz" in done.stdout


PUBLISH_TEST = """<launch>
  <node pkg="hear_pkg" type="talker.py" name="talker" />
  <test test-name="published" pkg="rostest" type="publishtest" time-limit="30">
    <rosparam param="topics">[{{name: chatter, timeout: 10}}, {{name: {quiet}, timeout: 1, negative: true}}]</rosparam>
  </test>
</launch>
"""


@pytest.mark.parametrize(("quiet", "code"), [("silence", 0), ("chatter", 1)],
                         ids=["silent topic", "published topic"])
def test_publishtest_checks_topics_are_published_or_not(ws, package, quiet, code):
    (package / "test" / "published.test").write_text(PUBLISH_TEST.format(quiet=quiet))
    done = ws.run("rostest", "hear_pkg", "published.test", timeout=120)
    assert done.returncode == code, done.stdout + done.stderr
    if code:
        assert "chatter was published, and should not have been" in done.stdout


PARAM_TEST = """<launch>
  <param name="rate" value="10" />
  <test test-name="rate_set" pkg="rostest" type="paramtest" time-limit="30">
    <param name="param_name_target" value="/rate" />
    <param name="param_value_expected" value="{expected}" />
    <param name="wait_time" value="2" />
  </test>
</launch>
"""


@pytest.mark.parametrize(("expected", "code"), [("10", 0), ("11", 1)], ids=["same", "other"])
def test_paramtest_checks_a_parameter(ws, package, expected, code):
    (package / "test" / "rate.test").write_text(PARAM_TEST.format(expected=expected))
    done = ws.run("rostest", "hear_pkg", "rate.test", timeout=120)
    assert done.returncode == code, done.stdout + done.stderr


def test_ctrl_c_during_a_test_ends_the_run_at_once_with_what_ran(ws, package):
    """The test running is stopped and fails; the next is not started (nor is its time limit
    waited for): the summary says so."""
    write_test(package, delay=60, extra="/>\n  <test test-name=\"second\" pkg=\"hear_pkg\" "
                                         "type=\"hear_test.py\" time-limit=\"60\"")
    proc = ws.start("rostest", "hear_pkg", "hear.test", output="run.out")
    ws.wait_for_output("[hear_test-2]: process started", 60, "run.out")
    began = time.monotonic()
    proc.send_signal(signal.SIGINT)
    assert proc.wait(30) == 1, ws.output("run.out")
    assert time.monotonic() - began < 15
    assert "[hear.rosunit-second][FAILURE]\n  the launch ended before it ran" \
        in ws.output("run.out")
