"""Every bad input: one clear message with file:line:col, exit 1, no traceback, nothing left."""

from __future__ import annotations

import subprocess

import pytest


def _nested_yaml(depth: int) -> str:
    lines, indent = ["launch:"], "  "
    for _ in range(depth):
        lines += [indent + "- group:", indent + "    children:"]
        indent += "      "
    return "\n".join([*lines, indent + "- log: {message: deep}"]) + "\n"


CASES = {
    "malformed-yaml": ("launch:\n  - arg: {name: x\n", "bad.launch.yaml:3:1: malformed YAML"),
    "malformed-xml": ("<launch><arg name='x'></launch>", "bad.launch.xml:1:25: malformed XML"),
    "root": ("robot: []\n", "bad.launch.yaml:1:1: the root key is 'robot'; expected 'launch'"),
    "two-keys": ("launch:\n  - {arg: {name: x}, let: {name: y, value: z}}\n",
                 "bad.launch.yaml:2:5: each list item must be a map with exactly one key"),
    "unknown-tag": ("launch:\n  - exectuable: {cmd: ls}\n",
                    "unknown tag 'exectuable' (did you mean 'executable'?)"),
    "unknown-attribute": ("launch:\n  - executable: {cmd: ls, outptu: screen}\n",
                          "bad.launch.yaml:2:27: 'executable' has no attribute 'outptu' "
                          "(did you mean 'output'?)"),
    "missing-attribute": ("launch:\n  - let: {name: x}\n",
                          "bad.launch.yaml:2:5: 'let' needs the attribute 'value'"),
    "wrong-type": ("launch:\n  - timer: {period: soon, children: []}\n",
                   "bad.launch.yaml:2:21: timer.period: expected a number, got 'soon'"),
    "if-and-unless": ("launch:\n  - log: {message: x, if: '1', unless: '0'}\n",
                      "'log' has both 'if' and 'unless'"),
    "bad-condition": ("launch:\n  - arg: {name: c, default: perhaps}\n"
                      "  - log: {message: x, if: $(var c)}\n",
                      "bad.launch.yaml:3:27: if: expected true, false, 1 or 0, got 'perhaps'"),
    "unknown-substitution": ("launch:\n  - log: {message: $(arg2 x)}\n",
                             "bad.launch.yaml:2:20: unknown substitution '$(arg2)'"),
    "unclosed-substitution": ("launch:\n  - log: {message: '$(var x'}\n",
                              "bad.launch.yaml:2:21: unclosed '$(var': expected ')'"),
    "set-parameter-no-value": ("launch:\n  - set_parameter: {name: x}\n",
                               "bad.launch.yaml:2:5: set_parameter needs 'name' and 'value'"),
    "undefined-var": ("launch:\n  - log: {message: 'hello $(var robto)'}\n",
                      "bad.launch.yaml:2:27: launch configuration 'robto' is not set"),
    "choice": ("launch:\n  - arg: {name: mode, default: simm, choice: [{value: sim}, "
               "{value: real}]}\n", "bad.launch.yaml:2:5: argument 'mode' is 'simm'; "
               "expected one of: sim, real (did you mean 'sim'?)"),
    "failing-command": ("launch:\n  - log: {message: \"$(command 'sh -c \\\"echo oops >&2; "
                        "exit 4\\\"')\"}\n", "failed with exit code 4; its stderr:\n    oops"),
    "eval-not-allowed": ("launch:\n  - log: {message: \"$(eval '__import__(1)')\"}\n",
                         "unknown name '__import__'"),
    "eval-fails": ("launch:\n  - log: {message: \"$(eval '1/0')\"}\n",
                   "ZeroDivisionError: division by zero"),
    "missing-executable": ("launch:\n  - executable: {cmd: sleeep 10}\n",
                           "bad.launch.yaml:2:5: executable 'sleeep' not found on PATH "
                           "(did you mean 'sleep'"),
    "missing-cwd": ("launch:\n  - executable: {cmd: ls, cwd: /no/such/folder}\n",
                    "cwd '/no/such/folder' does not exist"),
    "negative-timeout": ("launch:\n  - executable: {cmd: ls, sigkill_timeout: -2}\n",
                         "executable.sigkill_timeout: expected a number ≥ 0, got -2"),
    "include-missing": ("launch:\n  - include: {file: nowhere.launch.yaml}\n",
                        "bad.launch.yaml:2:5: included file 'nowhere.launch.yaml' does not exist"),
    # inputs that would hang or starve the launcher, or crash it without a line number
    "eval-factorial": ("launch:\n  - log: {message: \"$(eval 'math.factorial(100000000)')\"}\n",
                       "bad.launch.yaml:2:21: $(eval 'math.factorial(100000000)'): "
                       "factorial(100000000) would be too large"),
    "eval-format": ("launch:\n  - log: {message: \"$(eval '\\\"%0999999999d\\\" % 1')\"}\n",
                    "the width 999999999 is past the limit of 10000"),
    "for-too-long": ("launch:\n  - for:\n      len: 100000000\n      name: i\n      children:\n"
                     "        - log: {message: '$(index i)'}\n",
                     "bad.launch.yaml:2:5: for: 100,000,000 iterations is past the limit of "
                     "10,000"),
    "nul-byte": ('launch:\n  - log: {message: "a\0b"}\n',
                 "bad.launch.yaml:2:22: malformed YAML: control characters are not allowed"),
    "nested-groups": (_nested_yaml(3000), "levels deep; launcher reads YAML nested up to 100"),
    "nested-groups-xml": ("<launch>" + "<group>" * 3000 + "<log message='x'/>" +
                          "</group>" * 3000 + "</launch>",
                          "bad.launch.xml:1:702: <group> is nested 101 elements deep"),
    "bogus-encoding-xml": ('<?xml version="1.0" encoding="bogus-enc"?>\n<launch/>\n',
                           "bad.launch.xml:1:1: cannot decode the file: unknown encoding: "
                           "bogus-enc"),
    "non-action-py": ("from launch import LaunchDescription\n\n"
                      "def generate_launch_description():\n"
                      "    return LaunchDescription([42])\n",
                      "bad.launch.py:3: the LaunchDescription holds 42 (int) as entry 1"),
    "sys-exit-py": ("import sys\n\ndef generate_launch_description():\n    sys.exit(3)\n",
                    "bad.launch.py:4: the launch file called sys.exit(3)"),
    "module-exit-py": ("import sys\nsys.exit(0)\n", "bad.launch.py:2: the launch file called "
                                                     "sys.exit(0)"),
    "keyboard-interrupt-py": ("from launch import LaunchDescription\n\n"
                              "def generate_launch_description():\n"
                              "    raise KeyboardInterrupt\n",
                              "bad.launch.py:4: the launch file raised KeyboardInterrupt itself "
                              "(no Ctrl-C was pressed)"),
    "module-interrupt-py": ("x = 1\nraise KeyboardInterrupt('stop')\n",
                            "bad.launch.py:2: the launch file raised KeyboardInterrupt itself"),
}


def _suffix(name: str) -> str:
    return ".xml" if name.endswith("xml") else ".py" if name.endswith("-py") else ".yaml"



@pytest.mark.parametrize("name", list(CASES))
def test_bad_launch_file(ws, name):
    text, expected = CASES[name]
    path = ws.write(f"bad.launch{_suffix(name)}", text)
    result = ws.run("launch", str(path))
    assert result.returncode == 1, result.stdout + result.stderr
    message = result.stderr + result.stdout
    assert expected in message, message
    assert "Traceback" not in message
    assert str(path) in message


def test_an_included_python_file_raising_keyboard_interrupt_is_its_error(ws):
    """Loaded while the launch runs (an include), the file's own KeyboardInterrupt is its
    error at its line: exit 1, what was started is stopped, not a Ctrl-C's 130."""
    ws.write("inner.launch.py", "import time\nraise KeyboardInterrupt\n")
    ws.write("outer.launch.yaml", """
    launch:
      - executable: {cmd: sleep 30}
      - include: {file: inner.launch.py}
    """)
    result = ws.run("launch", "outer.launch.yaml", timeout=60)
    assert result.returncode == 1, result.stdout + result.stderr
    assert f"{ws.root}/inner.launch.py:2: the launch file raised KeyboardInterrupt itself" in \
        result.stdout + result.stderr
    assert "Traceback" not in result.stdout + result.stderr


def test_error_after_processes_started_stops_them(ws):
    ws.write("late.launch.yaml", """
    launch:
      - executable: {cmd: sleep 60}
      - timer: {period: 0.3, children: [{executable: {cmd: no-such-binary}}]}
    """)
    result = ws.run("launch", "late.launch.yaml")
    assert result.returncode == 1
    assert "executable 'no-such-binary' not found on PATH" in result.stdout
    assert "[sleep-1]: process stopped" in result.stdout


def test_required_argument_missing_on_the_command_line(ws):
    ws.write("req.launch.yaml", """
    launch:
      - arg: {name: robot_name, description: name of the robot to spawn}
      - executable: {cmd: sleep 60}
    """)
    result = ws.run("launch", "req.launch.yaml")
    assert result.returncode == 1
    assert "req.launch.yaml:2:5: required argument 'robot_name' not given; pass " \
           "robot_name:=VALUE" in result.stderr
    assert "name of the robot to spawn" in result.stderr
    assert "process started" not in result.stdout  # checked before anything ran


def test_a_misspelt_launch_argument_is_said_with_did_you_mean(ws):
    """ROS 2 takes `world_nmae:=x` silently; the launch says so, and runs on (the value is a
    configuration all the same, as in ROS 2). Arguments of included files count as declared."""
    ws.write("inner.launch.yaml", """
    launch:
      - arg: {name: robot_count, default: "1"}
    """)
    ws.write("outer.launch.yaml", """
    launch:
      - arg: {name: world_name, default: empty.sdf}
      - include: {file: inner.launch.yaml}
      - log: {message: "world $(var world_name), $(var robot_count) robots"}
    """)
    result = ws.run("launch", "outer.launch.yaml", "world_nmae:=arena.xml", "robot_count:=3")
    assert result.returncode == 0, result.stderr
    text = result.stdout + result.stderr
    assert "launch argument 'world_nmae' was given, but no launch file declares it (did you " \
           "mean 'world_name'?)" in text
    assert "robot_count" not in text.split("world empty.sdf")[0]  # declared by the include
    assert "world empty.sdf, 3 robots" in text


def test_malformed_assignment_on_the_command_line(ws):
    ws.write("ok.launch.yaml", "launch: []\n")
    result = ws.run("launch", "ok.launch.yaml", "world_name=arena.xml")
    assert result.returncode == 2  # a usage error, as argparse's own
    assert "malformed launch argument 'world_name=arena.xml': expected name:=value" in \
        result.stderr


def test_include_cycle(ws):
    ws.write("a.launch.yaml", "launch:\n  - include: {file: b.launch.yaml}\n")
    ws.write("b.launch.yaml", "launch:\n  - include: {file: a.launch.yaml}\n")
    result = ws.run("launch", "a.launch.yaml")
    assert result.returncode == 1 and "include cycle:" in result.stdout


@pytest.mark.parametrize("kind", ["missing", "folder", "binary", "format"])
def test_unreadable_files(ws, kind):
    if kind == "folder":
        (ws.root / "dir.launch.yaml").mkdir()
        target, expected = "dir.launch.yaml", "this is a folder, not a launch file"
    elif kind == "binary":
        (ws.root / "bin.launch.yaml").write_bytes(b"\xff\xfe\x00launch")
        target, expected = "bin.launch.yaml", "not UTF-8 text"
    elif kind == "format":
        ws.write("notes.txt", "launch: []\n")
        target, expected = "notes.txt", "cannot tell the launch file's format"
    else:
        target, expected = "missing.launch.yaml", "no such launch file"
    result = ws.run("launch", target)
    assert result.returncode == 1
    assert expected in result.stderr and "Traceback" not in result.stderr


def test_debug_adds_the_traceback(ws):
    ws.write("bad.launch.yaml", "launch:\n  - exectuable: {cmd: ls}\n")
    result = ws.run("launch", "bad.launch.yaml", "--debug")
    assert result.returncode == 1 and "Traceback" in result.stderr


def test_show_args_includes_statically_resolvable_includes(ws):
    ws.write("leaf.launch.yaml", "launch:\n  - arg: {name: leaf_arg, default: '1', "
                                 "description: from the leaf}\n")
    ws.write("mid.launch.xml", '<launch><arg name="mid_arg" description="middle" '
                               'default="a"/>'
                               '<include file="$(dirname)/leaf.launch.yaml"/>'
                               '<include file="$(var unknown_path)/x.launch.yaml"/></launch>')
    ws.write("top.launch.yaml", "launch:\n  - arg: {name: top_arg}\n"
                                "  - include: {file: mid.launch.xml}\n")
    result = ws.run("launch", "top.launch.yaml", "--show-args")
    out = result.stdout
    assert result.returncode == 0, result.stderr
    assert "'top_arg':" in out and "(required)" in out
    assert "'mid_arg':" in out and "middle" in out
    assert "'leaf_arg':" in out and "from the leaf" in out and "default: '1'" in out
    assert "could not be listed" in out and "unknown_path" in out


def test_print_shows_the_tree(ws):
    ws.write("p.launch.yaml", """
    launch:
      - arg: {name: world, default: robot.xml}
      - group:
          - executable: {cmd: "sim $(var world)", output: screen, if: "true"}
    """)
    result = ws.run("launch", "p.launch.yaml", "--print")
    assert result.returncode == 0
    assert "arg name='world' default='robot.xml'  -> 'robot.xml' (its default)" in result.stdout
    assert "    executable cmd='sim $(var world)' output='screen' if=true" in result.stdout
    overridden = ws.run("launch", "p.launch.yaml", "--print", "world:=arena.sdf")
    assert "arg name='world' default='robot.xml'  -> 'arena.sdf' (the command line)" in \
        overridden.stdout


def test_colour_follows_force_color_and_no_color(ws):
    ws.write("hello.launch.yaml", """
    launch:
      - executable: {cmd: "echo hello", output: screen}
    """)
    plain = ws.run("launch", "hello.launch.yaml")  # (a pipe: no colour)
    assert "\x1b[" not in plain.stdout and "hello" in plain.stdout
    ws.env["FORCE_COLOR"] = "1"
    forced = ws.run("launch", "hello.launch.yaml")
    assert "\x1b[" in forced.stdout and "hello" in forced.stdout
    ws.env["RCUTILS_COLORIZED_OUTPUT"] = "0"  # ROS 2's own switch wins
    assert "\x1b[" not in ws.run("launch", "hello.launch.yaml").stdout


# --- the command line: every parser's mistakes go through the one reporter -----------------
@pytest.mark.parametrize("args, expected", [
    (["tpoic", "list"], "error: launcher: argument COMMAND: invalid choice: 'tpoic' "),
    (["tpoic", "list"], "(did you mean 'topic'?) (see `launcher -h`)"),
    (["topic", "ehco", "/x"], "(did you mean 'echo'?) (see `launcher topic -h`)"),
    (["topic", "echo", "/x", "--onec"], "error: launcher topic echo: unrecognized arguments: "
                                        "--onec (did you mean '--once'?)"),
    (["router", "--lisen"], "error: launcher router: unrecognized arguments: --lisen "
                            "(did you mean '--listen'"),
    (["sim", "--gui-rte", "5"], "[sim] error: sim: unrecognized arguments: --gui-rte "
                                "(did you mean '--gui-rate' or"),
    (["sim", "--gui-rate", "500"], "[sim] error: sim: --gui-rate must be between 1 and"),
    (["sim", "snapshot"], "error: launcher sim snapshot: the following arguments are "
                          "required: -o/--output"),
    (["param", "get"], "error: launcher param get: the following arguments are required: "
                       "node, name (see `launcher param get -h`)"),
], ids=["command", "command-hint", "verb", "flag", "router", "sim", "sim-value", "snapshot",
        "missing"])
def test_command_line_mistakes_are_one_reported_line(ws, args, expected):
    done = ws.run(*args)
    assert done.returncode == 2, done.stderr
    assert expected in done.stderr and "usage:" not in done.stderr, done.stderr
    assert len(done.stderr.strip().splitlines()) == 1 and done.stdout == ""


def test_internal_entry_points_report_their_usage_too(ws):
    import sys

    for module in ("launcher.packages.entry", "launcher.nodes.load_parameters"):
        done = subprocess.run([sys.executable, "-m", module], capture_output=True, text=True,
                              env=ws.env, timeout=60)
        assert done.returncode == 2, done.stderr
        assert done.stderr.startswith(("error: usage: python -m ",
                                       "[load_parameters] error: usage: python -m ")), \
            done.stderr
