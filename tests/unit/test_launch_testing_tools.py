"""launch_testing's output tools (tools.text, tools.output), launch_testing_ros's output filter
and ament_index_python's resource index, as launch tests use them: matchers of expected text and
lines, filters of a process's output, expected output read from a file."""

from __future__ import annotations

import re

import pytest

from launcher import compat


@pytest.fixture(autouse=True)
def shims():
    compat.enable_in_process()


def test_a_text_expectation_is_found_and_a_list_of_them_in_order():
    from launch_testing.tools.text import build_text_match

    assert build_text_match("lo wo")("hello world") == (3, 8)
    assert build_text_match(["a", re.compile("c+")])("xxaycc") == (2, 6)
    assert build_text_match(["c", "a"])("abc") is None  # (out of order)
    assert build_text_match("hi\nthere")("hi\r\nthere") == (0, 8)  # (a pty's line endings)


def test_a_strict_text_expectation_is_the_whole_text():
    from launch_testing.tools.text import build_text_match

    assert build_text_match("abc", strict=True)("abc") == (0, 3)
    assert build_text_match("abc", strict=True)("abcd") is None


def test_a_line_expectation_finds_each_line_after_the_one_before():
    from launch_testing.tools.text import build_line_match

    assert build_line_match(["hello", re.compile(r"wor")])(["x hello", "y", "world!"]) == (0, 3)
    assert build_line_match("b", strict=True)(["b", "b"]) == (0, 2)
    assert build_line_match("b", strict=True)(["b", "c"]) is None
    with pytest.raises(ValueError, match="Unknown format for expected lines"):
        build_line_match(3)


def test_the_basic_output_filter_drops_pid_and_rc_lines_and_patterns():
    from launch_testing.tools import basic_output_filter

    assert basic_output_filter()("pid 12\nhello\nrc 0\n") == "hello\n"
    assert basic_output_filter([], [r"\[DEBUG\]"])("[DEBUG] x\nkept\n") == "kept\n"


def test_expect_output_takes_text_or_lines_and_strips_colours():
    from launch_testing.tools import expect_output

    assert expect_output("\x1b[31mred\x1b[0m\nblue", expected_lines=["red", "blue"], strict=True)
    assert expect_output(lines=["one", "two"], expected_text="one\ntwo")
    with pytest.raises(ValueError, match="Either lines or text"):
        expect_output("a", lines=["a"], expected_text="a")


def test_expected_output_comes_from_a_txt_file_or_else_a_regex_file(tmp_path):
    from launch_testing.tools import expected_output_from_file

    (tmp_path / "talker.txt").write_text("Publishing: 'Hello World: 1'\n")
    (tmp_path / "listener.regex").write_text(r"I heard: \d+" + "\n")
    assert expected_output_from_file(str(tmp_path / "talker")) == \
        ["Publishing: 'Hello World: 1'"]
    (pattern,) = expected_output_from_file(str(tmp_path / "listener"))
    assert pattern.match("I heard: 42")
    with pytest.raises(RuntimeError, match="could not find output check file"):
        expected_output_from_file(str(tmp_path / "missing"))


def ament_prefix(root, resource_type: str, name: str, content: str):
    folder = root / "share" / "ament_index" / "resource_index" / resource_type
    folder.mkdir(parents=True, exist_ok=True)
    (folder / name).write_text(content)
    return root


def test_resources_are_read_from_the_first_ament_prefix_that_has_them(tmp_path, monkeypatch):
    import ament_index_python

    first = ament_prefix(tmp_path / "a", "rmw_output_prefixes", "rmw_x", "[x] \n")
    second = ament_prefix(tmp_path / "b", "rmw_output_prefixes", "rmw_x", "[y] \n")
    ament_prefix(second, "packages", "demo", "")
    monkeypatch.setenv("AMENT_PREFIX_PATH", f"{first}:{second}")
    assert ament_index_python.get_resource("rmw_output_prefixes", "rmw_x") == \
        ("[x] \n", str(first))
    assert ament_index_python.has_resource("packages", "demo") == str(second)
    assert ament_index_python.get_resources("packages") == {"demo": str(second)}
    with pytest.raises(LookupError, match="Could not find the resource 'nope'"):
        ament_index_python.get_resource("packages", "nope")


def test_the_ros_output_filter_drops_an_rmws_registered_lines(tmp_path, monkeypatch):
    from launch_testing_ros.tools import basic_output_filter

    prefix = ament_prefix(tmp_path, "rmw_output_prefixes", "rmw_x", "[x] ")
    monkeypatch.setenv("AMENT_PREFIX_PATH", str(prefix))
    drop = basic_output_filter(filtered_rmw_implementation="rmw_x")
    assert drop("[x] noise\npid 3\nsignal\n") == "signal\n"
    assert basic_output_filter(filtered_rmw_implementation="rmw_y")("[x] kept\n") == "[x] kept\n"


class EndsRightAfterReady:
    """A launch service that visits the description's ReadyToTest, then ends at once (its one
    process done), as a launch of `[true, ReadyToTest()]` may before the tests look."""

    def __init__(self) -> None:
        self.loop = type("Loop", (), {"open_posting": lambda self: None})()
        self.ending = type("Ending", (), {"error": False})()

    def run(self, description, signals: bool = True) -> None:
        from launch_testing.actions import ReadyToTest

        pending = list(description.actions)
        while pending:
            action = pending.pop(0)
            if isinstance(action, ReadyToTest):
                action.execute(None)
            pending += list(getattr(action, "actions", []))


def test_a_launch_that_ends_after_its_ready_to_test_still_lets_the_tests_run():
    """launch_pytest's fixture waits for ReadyToTest; a launch that reached it and then ended
    (its processes done) before the test thread looked runs the tests, which judge the exits
    (a loaded machine reported "ReadyToTest was never reached: the launch ended first")."""
    from launch import LaunchDescription
    from launch_testing.actions import ReadyToTest

    from launcher.compat.testing.launch_pytest.threaded_launch import ThreadedLaunch

    ready = ReadyToTest()
    launch = ThreadedLaunch(EndsRightAfterReady, event_loop=None)
    launch.start(LaunchDescription([ready]), ready)
    launch.finish(auto_shutdown=False)
    assert launch.ended
    assert launch.wait_ready(0)
