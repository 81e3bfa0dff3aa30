"""Environment hooks: colcon's .dsv semantics, shell hooks, templates, order, errors."""

from __future__ import annotations

import random
from pathlib import Path

import pytest

from launcher.errors import LaunchError, ParseError
from launcher.packages.dsv import HookEnvironment, apply_dsv
from launcher.packages.hooks import apply_hooks, ordered
from tests.support.packages import index_for, make_tree, manifest

PREFIX = Path("/opt/pfx")


def dsv(text: str, env: dict[str, str] | None = None, sourced: list | None = None) -> dict:
    hook_env = HookEnvironment(dict(env or {}))
    apply_dsv(Path("h.dsv"), text, PREFIX, hook_env,
              lambda path, where: (sourced if sourced is not None else []).append(path))
    return hook_env.finish()


def test_prepend_non_duplicate_order_and_duplicates():
    env = dsv("prepend-non-duplicate;P;a;b\nprepend-non-duplicate;P;/abs;share\n",
              {"P": "/opt/pfx/share:/old"})
    # a and b prepended in order (b ends first); share already present: skipped, not moved
    assert env["P"] == "/abs:/opt/pfx/b:/opt/pfx/a:/opt/pfx/share:/old"


def test_values_empty_relative_absolute_and_append():
    env = dsv("append-non-duplicate;A;;lib;/x\nappend-non-duplicate;A;lib\n", {"A": "/first"})
    assert env["A"] == "/first:/opt/pfx:/opt/pfx/lib:/x"


def test_if_exists_skips_missing_paths(tmp_path):
    (tmp_path / "real").mkdir()
    env = dsv(f"prepend-non-duplicate-if-exists;R;{tmp_path}/real;{tmp_path}/missing\n")
    assert env["R"] == f"{tmp_path}/real"


def test_set_and_set_if_unset(tmp_path):
    env = HookEnvironment({"KEEP": "mine"})
    apply_dsv(Path("h.dsv"), f"set;S;{tmp_path.name}\nset;T;literal value\nset-if-unset;KEEP;no\n"
              "set-if-unset;NEW;yes\n", tmp_path.parent, env, lambda *a: None)
    out = env.finish()
    assert out["S"] == str(tmp_path)  # prefix/VALUE exists: used
    assert out["T"] == "literal value" and out["KEEP"] == "mine" and out["NEW"] == "yes"


def test_strip_colons_only_for_variables_unset_at_start():
    env = HookEnvironment({"SET": "x"})
    env.values["SET"] = ":x:"
    env.note("SET")
    env.note("UNSET")
    env.values["UNSET"] = ":/a:"
    out = env.finish()
    assert out == {"SET": ":x:", "UNSET": "/a"}


def test_source_and_comments():
    sourced = []
    dsv("# a comment\n\nsource;share/p/hook/x.sh\n", sourced=sourced)
    assert sourced == [PREFIX / "share/p/hook/x.sh"]


@pytest.mark.parametrize("text, expected", [
    ("prepend-non-duplicate PATH x", "h.dsv:1:1: expected TYPE;ARGUMENTS"),
    ("\nprepend-unique;P;x", "h.dsv:2:1: unknown type 'prepend-unique' (did you mean"),
    ("set;ONLY", "h.dsv:1:1: too few arguments for 'set': expected set;NAME;VALUE"),
    ("prepend-non-duplicate;P", "too few arguments for 'prepend-non-duplicate'"),
    ("source", "expected TYPE;ARGUMENTS"),
], ids=["no-semicolon", "unknown-type", "few-set", "few-prepend", "source-bare"])
def test_bad_dsv_lines(text, expected):
    with pytest.raises(ParseError) as info:
        dsv(text)
    assert expected in str(info.value)


def seed_workspace(root: Path) -> Path:
    """The seed's loc_gazebo layout: hooks/<pkg>.dsv.in and .sh.in next to each other."""
    return make_tree(root, {
        "loc_gazebo/package.xml": manifest("loc_gazebo"),
        "loc_gazebo/worlds/world.xml": "<mujoco/>",
        "loc_gazebo/hooks/loc_gazebo.dsv.in":
            "prepend-non-duplicate;GZ_SIM_RESOURCE_PATH;share;"
            "@CMAKE_INSTALL_PREFIX@/share/loc_gazebo/worlds\n",
        "loc_gazebo/hooks/loc_gazebo.sh.in":
            'ament_prepend_unique_value GZ_SIM_RESOURCE_PATH "$AMENT_CURRENT_PREFIX/share/'
            '@PROJECT_NAME@/never"\n',
        "shelly/package.xml": manifest("shelly", ("loc_gazebo",)),
        "shelly/hooks/shelly.sh":
            'ament_prepend_unique_value GZ_SIM_RESOURCE_PATH "$AMENT_CURRENT_PREFIX/share/'
            'shelly/models"\nament_append_value OTHER one\nament_append_value OTHER two\n'
            'ament_append_unique_value OTHER one\n',
    })


def test_seed_hooks_dsv_wins_and_shell_hooks_run(tmp_path):
    ws = seed_workspace(tmp_path / "ws")
    index = index_for(ws, tmp=tmp_path)
    env = apply_hooks(index, {"PATH": "/usr/bin:/bin"})
    parts = env["GZ_SIM_RESOURCE_PATH"].split(":")
    # shelly depends on loc_gazebo: applied later, so its path ends up first
    assert parts[0] == str(ws / "shelly/models")
    assert str(ws / "loc_gazebo/worlds") in parts
    assert not any("never" in p for p in parts)  # the .dsv won over the .sh
    assert env["OTHER"] == "one:two"
    assert "AMENT_CURRENT_PREFIX" not in env


def test_dependency_order(tmp_path):
    ws = make_tree(tmp_path / "ws", {"z/package.xml": manifest("zeta"),
                                     "a/package.xml": manifest("alpha", ("zeta",)),
                                     "m/package.xml": manifest("mid", ("alpha",))})
    names = [p.name for p in ordered(index_for(ws, tmp=tmp_path)) if p.origin == "workspace"]
    assert names == ["zeta", "alpha", "mid"]


@pytest.mark.parametrize("files, expected", [
    ({"p/hooks/p.dsv.in": "set;X;@CMAKE_INSTAL_PREFIX@\n"},
     "p.dsv.in:1:7: unknown template variable @CMAKE_INSTAL_PREFIX@ (did you mean "
     "'CMAKE_INSTALL_PREFIX'"),
    ({"p/hooks/p.sh": "echo broken >&2\nexit 3\n"}, "hook failed with exit status 3; its "
                                                   "stderr:\nbroken"),
    ({"p/hooks/p.dsv": "source;share/p/hooks/nothere.dsv\n"}, "nothere.dsv' does not exist"),
    ({"p/hooks/p.dsv": "source;share/p/hooks/q.dsv\n",
      "p/hooks/q.dsv": "source;share/p/hooks/p.dsv\n"}, "hook cycle through 'source'"),
], ids=["unknown-template-variable", "shell-hook-fails", "source-missing", "source-cycle"])
def test_bad_hooks(tmp_path, files, expected):
    ws = make_tree(tmp_path / "ws", {"p/package.xml": manifest("p"), **files})
    with pytest.raises(LaunchError) as info:
        apply_hooks(index_for(ws, tmp=tmp_path), {"PATH": "/usr/bin:/bin"})
    assert expected in str(info.value)


HANGS = """# waits for a device that never comes
export ROBOT_PORT=/dev/ttyUSB0
sleep 987
export AFTER=1
"""


@pytest.mark.parametrize("name, text, expected", [
    ("p.sh", "export A=1\nexit 3\n", "p.sh:2: hook failed with exit status 3"),
    ("p.sh", "A=1\nB=2\n[ -n \"$NOT_SET_XYZ\" ] || return 4\nC=3\n", "p.sh:3: hook failed"),
    ("p.sh", HANGS, "p.sh:3: hook did not finish within 0.5 s and was stopped"),
    ("p.bash", "A=1\nX=987\nsleep $X\n", "p.bash:3: hook did not finish within 0.5 s"),
    ("p.sh", "A=1\nf() {\n  sleep $1\n}\nf 987\n", "p.sh:3: hook did not finish"),
], ids=["exit", "last-command", "never-ends", "bash-never-ends", "in-a-function"])
def test_a_shell_hook_that_fails_or_never_ends_is_located_and_leaves_nothing(
        tmp_path, name, text, expected):
    """The hook's file and the line it was at: the shell's trace says which command ran last
    (bash gives the line; Debian's sh has no $LINENO, so the command is found in the file)."""
    import psutil

    # (a number of this test's own: the other cases, on other workers, sleep too)
    seconds = str(random.randint(10_000, 99_999))
    text = text.replace("987", seconds)
    ws = make_tree(tmp_path / "ws", {"p/package.xml": manifest("p"), f"p/hooks/{name}": text})
    with pytest.raises(LaunchError) as info:
        apply_hooks(index_for(ws, tmp=tmp_path), {"PATH": "/usr/bin:/bin",
                                                  "LAUNCHER_HOOK_TIMEOUT": "0.5"})
    assert expected in str(info.value)
    assert str(info.value).startswith(str(ws / "p" / "hooks" / name))
    assert "\x1f" not in str(info.value)  # the shell's trace is not shown as the hook's words
    left = [p for p in psutil.process_iter(["cmdline"])
            if p.info["cmdline"] == ["sleep", seconds]]
    assert not left


def test_a_bad_hook_timeout_is_said(tmp_path):
    ws = make_tree(tmp_path / "ws", {"p/package.xml": manifest("p"), "p/hooks/p.sh": "A=1\n"})
    with pytest.raises(LaunchError, match="LAUNCHER_HOOK_TIMEOUT is 'soon'; expected a number"):
        apply_hooks(index_for(ws, tmp=tmp_path), {"PATH": "/usr/bin:/bin",
                                                  "LAUNCHER_HOOK_TIMEOUT": "soon"})
