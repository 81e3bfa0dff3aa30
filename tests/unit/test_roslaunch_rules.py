"""roslaunch's loader rules, each with its expected outcome read from roslaunch's source
(ros/ros_comm tools/roslaunch/src/roslaunch, 1.15/1.16):
  * loader.py LoaderContext.add_arg: an arg declared twice in one file is "arg 'x' has
    already been declared"; an arg with value= is a constant, and a value given for it before
    (command line, include) is "cannot override arg 'x', which has already been set", unless
    the file was included with pass_all_args;
  * loader.py post_process_include_args: an include passing an arg its file does not
    declare is "unused args [x] for include of [file]";
  * xmlloader.py: a tag under a false if=/unless= is skipped whole (so an arg may be
    declared under opposite conditions); <test> is rostest's (roslaunch does not run it);
  * substitution_args.py resolve_args: $(eval …) is evaluated only when the attribute starts
    with '$(eval ' and ends with ')'.
(<machine>'s rules: test_machines.py.)"""

from __future__ import annotations

import pytest

from launcher.errors import LaunchError, ParseError
from launcher.frontend.loader import load_file
from tests.support.fake_service import run


def launch(tmp_path, text: str, name: str = "top.launch"):
    path = tmp_path / name
    path.write_text(text)
    return path


def test_an_arg_declared_twice_in_a_file_groups_included(tmp_path):
    path = launch(tmp_path, '<launch>\n<arg name="a" default="1"/>\n<group>\n'
                            '<arg name="a" default="2"/>\n</group>\n</launch>\n')
    with pytest.raises(ParseError, match=r"arg 'a' has already been declared \(at line 2\)") \
            as caught:
        load_file(path)
    assert caught.value.location.line == 4


def test_an_arg_declared_under_opposite_conditions_is_declared_once(tmp_path):
    path = launch(tmp_path, '<launch>\n<arg name="paused" default="false"/>\n'
                            '<arg unless="$(arg paused)" name="flag" value=""/>\n'
                            '<arg if="$(arg paused)" name="flag" value="-u"/>\n</launch>\n')
    context, _ = run(load_file(path))
    assert context.configurations["flag"] == ""


def test_a_constant_arg_takes_no_value_from_the_command_line(tmp_path):
    path = launch(tmp_path, '<launch>\n  <arg name="a" value="1"/>\n</launch>\n')
    assert run(load_file(path))[0].configurations["a"] == "1"
    with pytest.raises(LaunchError, match="cannot override arg 'a', which has already been "
                                          "set"):
        run(load_file(path), {"a": "2"})


def test_a_constant_arg_takes_no_value_from_an_include_unless_all_args_pass(tmp_path):
    launch(tmp_path, '<launch>\n  <arg name="a" value="1"/>\n</launch>\n', "inner.launch")
    passing = launch(tmp_path, '<launch>\n<include file="$(dirname)/inner.launch">\n'
                               '  <arg name="a" value="2"/>\n</include>\n</launch>\n')
    with pytest.raises(LaunchError, match="cannot override arg 'a'"):
        run(load_file(passing))
    every = launch(tmp_path, '<launch>\n<arg name="a" default="2"/>\n'
                             '<include file="$(dirname)/inner.launch" pass_all_args="true"/>\n'
                             '</launch>\n', "every.launch")
    run(load_file(every))  # pass_all_args: the included file's value= wins, no error


def test_an_include_passing_an_undeclared_arg(tmp_path):
    launch(tmp_path, '<launch>\n  <arg name="a" default="1"/>\n</launch>\n', "inner.launch")
    path = launch(tmp_path, '<launch>\n<include file="$(dirname)/inner.launch">\n'
                            '  <arg name="a" value="2"/>\n  <arg name="zz" value="1"/>\n'
                            '</include>\n</launch>\n')
    with pytest.raises(LaunchError, match=r"unused args \[zz\] for include of \[.*inner"
                                          r"\.launch\]") as caught:
        run(load_file(path))
    assert caught.value.location.line == 2


@pytest.mark.parametrize("value", ["x$(eval 1+1)", "$(eval 1+1) cm", "$(eval 1)$(eval 2)x"])
def test_eval_only_as_the_whole_attribute(tmp_path, value):
    path = launch(tmp_path, f'<launch>\n<param name="p" value="{value}"/>\n</launch>\n')
    with pytest.raises(ParseError, match=r"evaluates \$\(eval …\) only as the whole "
                                         "attribute"):
        load_file(path)


def test_a_test_tag_is_not_run_by_roslaunch(tmp_path):
    def started(tag: str) -> list:
        path = launch(tmp_path, f'<launch>\n<{tag} name="t" test-name="t" pkg="p" '
                                f'type="check_tag_exe"/>\n</launch>\n', f"{tag}.launch")
        try:
            _, service = run(load_file(path))
        except LaunchError:
            return ["failed to resolve: it was going to run"]
        return [s for s in service.specs if any(a.endswith("check_tag_exe") for a in s.argv)]

    assert started("node")  # the same entry as a node is run
    assert not started("test")


@pytest.mark.parametrize("condition", ['if="yes"', 'unless="maybe"', 'if=""'])
def test_a_condition_that_is_not_a_boolean(tmp_path, condition):
    """loader.convert_value(value, 'bool'): true or 1, false or 0 (any case), else an
    error."""
    path = launch(tmp_path, f'<launch>\n<param name="x" value="1" {condition}/>\n</launch>\n')
    with pytest.raises(LaunchError, match=r"expected true, false, 1 or 0") as caught:
        run(load_file(path))
    assert caught.value.location.line == 2


def test_conditions_read_as_roslaunch_reads_them_and_never_both(tmp_path):
    for condition, kept in (('if="TRUE"', True), ('if="0"', False), ('unless="False"', True),
                            ('unless="1"', False)):
        path = launch(tmp_path, f'<launch>\n<param name="x" value="1" {condition}/>\n'
                                '</launch>\n')
        context, _ = run(load_file(path))
        assert any("x" in str(item) for item in context.configurations.get(
            "<global_parameters>", ())) == kept, condition
    both = launch(tmp_path, '<launch>\n<param name="x" value="1" if="true" unless="false"/>'
                            '\n</launch>\n')
    with pytest.raises(ParseError, match=r"<param> has both if= and unless=") as caught:
        load_file(both)
    assert caught.value.location.line == 2


# --- roslaunch's rosparam and env, as real roslaunch 1.15 dumps them (--dump-params) -------
def _dump(tmp_path, text):
    import os
    import subprocess
    import sys

    import yaml

    (tmp_path / "t.launch").write_text(text)
    done = subprocess.run([sys.executable, "-m", "launcher", "roslaunch", "--dump-params",
                           "t.launch"], cwd=tmp_path, capture_output=True, text=True,
                          timeout=60, env=dict(os.environ, LAUNCHER_CACHE_DIR=str(tmp_path)))
    assert done.returncode == 0, done.stderr
    return yaml.safe_load(done.stdout)


def test_a_rosparams_yaml_is_taken_as_written_without_subst_value(tmp_path):
    dumped = _dump(tmp_path, '<launch><arg name="who" default="world"/>'
                             '<rosparam>greet: hello $(arg who)</rosparam>'
                             '<rosparam subst_value="true">greet2: hello $(arg who)</rosparam>'
                             '</launch>')
    assert (dumped["/greet"], dumped["/greet2"]) == ("hello $(arg who)", "hello world")


def test_rad_and_deg_in_a_rosparams_yaml_are_radians(tmp_path):
    import math

    dumped = _dump(tmp_path, "<launch><rosparam>angle: rad(pi/2)\nhalf: deg(180)\n"
                             "tagged: !degrees 90</rosparam>"
                             '<param name="y" type="yaml" value="rad(2*pi)"/></launch>')
    assert dumped["/angle"] == math.pi / 2 and dumped["/half"] == math.pi
    assert dumped["/tagged"] == math.pi / 2 and dumped["/y"] == 2 * math.pi


def test_an_env_tag_sets_the_nodes_environment_not_the_one_optenv_reads(tmp_path, monkeypatch):
    monkeypatch.delenv("LAUNCHER_TEST_SEEN", raising=False)
    dumped = _dump(tmp_path, '<launch><env name="LAUNCHER_TEST_SEEN" value="set"/>'
                             '<param name="seen" value="$(optenv LAUNCHER_TEST_SEEN unset)"/>'
                             '</launch>')
    assert dumped["/seen"] == "unset"
