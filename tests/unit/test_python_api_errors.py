"""Bad input through launch's Python API: each said at the user's file and line, naming what
was wrong, never as a traceback of launcher's own."""

from __future__ import annotations

import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from launcher.errors import LaunchError, ParseError
from launcher.frontend.loader import load_file
from tests.support.fake_service import run

HEAD = "from launch import LaunchDescription, Action, Substitution\n" \
       "from launch.actions import ExecuteProcess, OpaqueFunction, LogInfo\n"


def launch_file(tmp_path: Path, body: str) -> Path:
    from launcher import compat

    compat.enable_in_process()
    path = tmp_path / "bad.launch.py"
    path.write_text(HEAD + textwrap.dedent(body))
    return path


def failure(tmp_path: Path, body: str) -> LaunchError:
    with pytest.raises(LaunchError) as raised:
        run(load_file(launch_file(tmp_path, body)))
    return raised.value


def test_an_opaque_function_that_raises_is_said_at_its_line(tmp_path):
    error = failure(tmp_path, """
        def broken(context):
            raise RuntimeError("opaque broke")

        def generate_launch_description():
            return LaunchDescription([OpaqueFunction(function=broken)])
    """)
    assert str(error.location) == f"{tmp_path / 'bad.launch.py'}:5"
    assert "RuntimeError: opaque broke" in error.message


def test_an_opaque_function_that_returns_no_actions_is_said_at_its_definition(tmp_path):
    error = failure(tmp_path, """
        def counts(context):
            return 42

        def generate_launch_description():
            return LaunchDescription([OpaqueFunction(function=counts)])
    """)
    assert str(error.location) == f"{tmp_path / 'bad.launch.py'}:4"
    assert "returned 42 (int); expected launch actions" in error.message


def test_a_custom_actions_execute_that_raises_is_said_at_its_line(tmp_path):
    error = failure(tmp_path, """
        class Mine(Action):
            def execute(self, context):
                return {}["key"]

        def generate_launch_description():
            return LaunchDescription([Mine()])
    """)
    assert str(error.location) == f"{tmp_path / 'bad.launch.py'}:6"
    assert error.message == "Mine raised KeyError: 'key'"


def test_a_substitution_that_returns_no_text_is_said_at_its_perform(tmp_path):
    error = failure(tmp_path, """
        class Number(Substitution):
            def perform(self, context):
                return 7

        def generate_launch_description():
            return LaunchDescription([LogInfo(msg=Number())])
    """)
    assert str(error.location) == f"{tmp_path / 'bad.launch.py'}:5"
    assert "Number.perform() returned 7 (int); a substitution returns text" in error.message


def test_a_command_that_is_a_number_is_said_where_the_action_is_made(tmp_path):
    with pytest.raises(ParseError) as raised:
        load_file(launch_file(tmp_path, """
            def generate_launch_description():
                return LaunchDescription([
                    ExecuteProcess(cmd=42)])
        """))
    assert str(raised.value).startswith(f"{tmp_path / 'bad.launch.py'}:6: ")
    assert "ExecuteProcess(cmd=42): expected the command as a list of words" in \
        str(raised.value)


def test_an_import_of_a_name_launch_lacks_names_the_nearest(tmp_path):
    with pytest.raises(ParseError) as raised:
        load_file(launch_file(tmp_path, "from launch.actions import ExecuteProces\n"))
    assert str(raised.value).startswith(f"{tmp_path / 'bad.launch.py'}:3: ")
    assert "(did you mean 'ExecuteProcess'" in str(raised.value)


def test_a_launch_service_run_twice_is_said_at_the_second_run(tmp_path):
    script = tmp_path / "twice.py"
    script.write_text(textwrap.dedent("""
        import sys
        from launch import LaunchDescription, LaunchService
        service = LaunchService()
        service.include_launch_description(LaunchDescription([]))
        service.run()
        sys.exit(service.run())
    """))
    done = subprocess.run([sys.executable, "-c", "from launcher import compat; "
                           "compat.enable_in_process(); import runpy; "
                           f"runpy.run_path({str(script)!r}, run_name='__main__')"],
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 1, done.stderr
    assert f"{script}:7: LaunchService.run() was called a second time" in done.stderr
    assert "Traceback" not in done.stderr


def test_a_launch_tests_description_that_raises_is_said_at_its_line(tmp_path):
    from launcher import compat

    compat.enable_in_process()
    from launch_testing.loader import TestFileError, TestRun

    path = tmp_path / "test_bad.py"
    path.write_text("def generate_test_description():\n    return {}['missing']\n")
    namespace: dict = {}
    exec(compile(path.read_text(), str(path), "exec"), namespace)  # (the test's own file)
    run_ = TestRun("test_bad", namespace["generate_test_description"], {}, None, None)
    with pytest.raises(TestFileError, match=rf"^{path}:2: generate_test_description raised "
                                            r"KeyError: 'missing'$"):
        run_.description(lambda: None)
