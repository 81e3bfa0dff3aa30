"""Action semantics, visited without a runtime (the spawner is faked)."""

import pytest

from launcher.errors import LaunchError
from tests.unit.helpers import run, yaml_description


def test_arg_defaults_choices_and_required():
    description = yaml_description("""
    launch:
      - arg: {name: mode, default: sim, choice: [{value: sim}, {value: real}]}
    """)
    context, _ = run(description)
    assert context.configurations["mode"] == "sim"
    with pytest.raises(LaunchError, match="argument 'mode' is 'rael'; expected one of: sim, "
                                          "real \\(did you mean 'real'\\?\\)"):
        run(description, {"mode": "rael"})
    required = yaml_description("""
    launch:
      - arg: {name: robot, description: which robot to spawn}
    """)
    with pytest.raises(LaunchError) as info:
        run(required)
    assert "required argument 'robot' not given; pass robot:=VALUE" in str(info.value)
    assert "which robot to spawn" in str(info.value)
    assert str(info.value).startswith("test.launch.yaml:2:5:")


def test_group_scoping_and_forwarding():
    description = yaml_description("""
    launch:
      - let: {name: a, value: outer}
      - group:
          - let: {name: a, value: inner}
          - log: {message: "in group: $(var a)"}
      - group:
          forwarding: false
          keep: [{name: b, value: kept}]
          children:
            - log: {message: "b=$(var b) a=$(var a missing)"}
      - group:
          scoped: false
          children:
            - let: {name: leaked, value: yes}
      - log: {message: "after: $(var a) $(var leaked)"}
    """)
    _, service = run(description)
    messages = [m for _, m in service.logs]
    assert messages == ["in group: inner", "b=kept a=missing", "after: outer yes"]


def test_include_arguments_leak_unless_scoped(tmp_path):
    (tmp_path / "child.launch.yaml").write_text(
        "launch:\n  - arg: {name: x}\n  - let: {name: from_child, value: $(var x)}\n")
    (tmp_path / "top.launch.yaml").write_text("""launch:
  - include: {file: child.launch.yaml, arg: [{name: x, value: "1"}]}
  - log: {message: "leaked=$(var from_child)"}
  - include: {file: $(dirname)/child.launch.yaml, scoped: true, arg: [{name: x, value: "2"}]}
  - log: {message: "still=$(var from_child)"}
""")
    from launcher.frontend.loader import load_file

    _, service = run(load_file(tmp_path / "top.launch.yaml"))
    assert [m for _, m in service.logs] == ["leaked=1", "still=1"]


def test_include_missing_required_argument_names_it(tmp_path):
    (tmp_path / "child.launch.yaml").write_text(
        "launch:\n  - arg: {name: robot_name, description: the entity name}\n")
    (tmp_path / "top.launch.yaml").write_text("launch:\n  - include: {file: child.launch.yaml}\n")
    from launcher.frontend.loader import load_file

    with pytest.raises(LaunchError) as info:
        run(load_file(tmp_path / "top.launch.yaml"))
    assert "child.launch.yaml:2:5: required argument 'robot_name' not given" in str(info.value)


def test_include_cycle_and_missing_file(tmp_path):
    (tmp_path / "a.launch.yaml").write_text("launch:\n  - include: {file: b.launch.xml}\n")
    (tmp_path / "b.launch.xml").write_text('<launch><include file="a.launch.yaml"/></launch>')
    (tmp_path / "c.launch.yaml").write_text("launch:\n  - include: {file: nothere.launch.yaml}\n")
    from launcher.frontend.loader import load_file

    with pytest.raises(LaunchError, match="include cycle: .*a.launch.yaml -> .*b.launch.xml -> "
                                          ".*a.launch.yaml"):
        run(load_file(tmp_path / "a.launch.yaml"))
    with pytest.raises(LaunchError) as info:
        run(load_file(tmp_path / "c.launch.yaml"))
    assert "c.launch.yaml:2:5: included file 'nothere.launch.yaml' does not exist" in \
        str(info.value)


def test_loops():
    description = yaml_description("""
    launch:
      - arg: {name: count, default: "3"}
      - for:
          len: $(var count)
          name: i
          children:
            - log: {message: "robot_$(index i)"}
      - for_each:
          values: "{name: a, x: 1};{name: b}"
          children:
            - log: {message: "$(for-var name) at $(for-var x 0)"}
    """)
    _, service = run(description)
    assert [m for _, m in service.logs] == ["robot_0", "robot_1", "robot_2", "a at 1", "b at 0"]


def test_environment_actions():
    description = yaml_description("""
    launch:
      - set_env: {name: A, value: one}
      - append_env: {name: P, value: /x}
      - append_env: {name: P, value: /y}
      - append_env: {name: P, value: /w, prepend: true}
      - unset_env: {name: GONE}
      - executable: {cmd: env}
      - reset_env: {}
      - executable: {cmd: env}
    """)
    _, service = run(description, environment={"PATH": "/usr/bin:/bin", "GONE": "1"})
    first, second = service.specs
    assert first.env["A"] == "one" and first.env["P"] == "/w:/x:/y" and "GONE" not in first.env
    assert "A" not in second.env and second.env["GONE"] == "1"


def test_conditions():
    description = yaml_description("""
    launch:
      - arg: {name: gui, default: "false"}
      - log: {message: shown, unless: $(var gui)}
      - log: {message: hidden, if: $(var gui)}
      - log: {message: eval, if: "$(eval '2 > 1')"}
    """)
    _, service = run(description)
    assert [m for _, m in service.logs] == ["shown", "eval"]


def test_executable_errors_are_clear(tmp_path):
    for text, expected in [
        ("{cmd: no-such-prog-xyz}", "executable 'no-such-prog-xyz' not found on PATH"),
        (f"{{cmd: ls, cwd: {tmp_path}/nowhere}}", "cwd '"),
        ("{cmd: ./missing.sh}", "executable './missing.sh' does not exist"),
    ]:
        description = yaml_description(f"launch:\n  - executable: {text}\n")
        with pytest.raises(LaunchError) as info:
            run(description)
        assert str(info.value).startswith("test.launch.yaml:2:5: ") and expected in \
            str(info.value)


def test_output_modes_and_labels():
    description = yaml_description("""
    launch:
      - executable: {cmd: /bin/echo a, output: screen}
      - executable: {cmd: /bin/echo b, name: talker}
      - executable: {cmd: /bin/echo c, output: own_log, launch-prefix: "nice -n 5"}
    """)
    _, service = run(description)
    screen, default, own = service.specs
    assert screen.label == "echo-1" and screen.stdout_to == {"screen"}
    assert default.label == "talker-2" and default.stdout_to == {"log"} and \
        default.stderr_to == {"log", "screen"}
    assert own.stdout_to == {"own_log"} and own.argv[:3] == ["nice", "-n", "5"]


def test_shell_gets_the_text_whole():
    description = yaml_description("""
    launch:
      - let: {name: msg, value: "it's here"}
      - executable: {cmd: "echo \\"$(var msg)\\" | wc -c", shell: true}
    """)
    _, service = run(description)
    assert service.specs[0].argv == ["/bin/sh", "-c", "echo \"it's here\" | wc -c"]


def test_which_programs_may_join_the_graph(tmp_path):
    """The launch starts the graph's router with the first of these (not for sleep or sh);
    the path is the one the spawn check found."""
    import shutil
    import sys

    from launcher.description.actions.executable import _check_runnable, _may_join_graph

    tool = tmp_path / "bin" / "gz"
    tool.parent.mkdir()
    tool.write_text("#!/bin/sh\n")
    tool.chmod(0o755)
    env = {"PATH": f"/usr/bin:/bin:{tool.parent}"}
    assert not _may_join_graph(_check_runnable("sleep", env, None))
    assert not _may_join_graph(_check_runnable("/bin/sh", env, None))
    assert _may_join_graph(_check_runnable("gz", env, None))
    assert _may_join_graph(_check_runnable("./bin/gz", env, str(tmp_path)))
    assert _may_join_graph(sys.executable)
    python = shutil.which("python3", path="/usr/bin:/bin")
    assert python is None or _may_join_graph(python)
