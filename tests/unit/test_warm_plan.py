"""Which processes the warm start takes (runtime/warm.py's `planned`), read from files and
PATH that each test makes: the rest start cold."""

from __future__ import annotations

import os
import sys

import pytest

from launcher.runtime.warm import own_module, planned

PYTHON = os.path.realpath(sys.executable)


@pytest.fixture
def bin_dir(tmp_path):
    """A PATH folder whose python3 is this interpreter (as a venv's is)."""
    folder = tmp_path / "bin"
    folder.mkdir()
    (folder / "python3").symlink_to(PYTHON)
    return folder


def env_for(bin_dir) -> dict[str, str]:
    return {"PATH": f"{bin_dir}:/usr/bin:/bin"}


def executable(path, text: str) -> str:
    path.write_text(text)
    path.chmod(0o755)
    return str(path)


@pytest.mark.parametrize("line", ["#!/usr/bin/env python3", "#!python3"])
def test_a_script_whose_shebang_finds_this_interpreter_is_taken(tmp_path, bin_dir, line):
    script = executable(tmp_path / "node.py", f"{line}\nprint(1)\n")
    plan = planned([script, "a"], env_for(bin_dir), str(tmp_path), sys.executable)
    assert plan is not None and (plan.run, plan.target, plan.argv) == ("script", script, ["a"])
    assert plan.shown == [line.split()[-1].removeprefix("#!"), script, "a"]


def test_a_script_for_another_python_starts_cold(tmp_path, bin_dir):
    script = executable(tmp_path / "node.py", "#!/opt/other/python3\nprint(1)\n")
    assert planned([script], env_for(bin_dir), str(tmp_path), sys.executable) is None


def test_interpreter_options_start_cold(tmp_path, bin_dir):
    executable(tmp_path / "node.py", "print(1)\n")
    assert planned([str(bin_dir / "python3"), "-u", "node.py"], env_for(bin_dir),
                   str(tmp_path), sys.executable) is None


def test_a_module_run_is_taken_with_its_arguments(tmp_path, bin_dir):
    plan = planned([str(bin_dir / "python3"), "-m", "pkg.mod", "x"], env_for(bin_dir),
                   str(tmp_path), sys.executable)
    assert plan is not None and (plan.run, plan.target, plan.argv) == ("module", "pkg.mod",
                                                                      ["x"])


def test_a_missing_working_directory_starts_cold(tmp_path, bin_dir):
    script = executable(tmp_path / "node.py", "#!/usr/bin/env python3\n")
    assert planned([script], env_for(bin_dir), str(tmp_path / "gone"), sys.executable) is None


def test_turned_off_every_process_starts_cold(tmp_path, bin_dir):
    script = executable(tmp_path / "node.py", "#!/usr/bin/env python3\n")
    env = {**env_for(bin_dir), "LAUNCHER_WARM_START": "0"}
    assert planned([script], env, str(tmp_path), sys.executable) is None


def test_launchers_own_node_is_imported_by_its_server_a_users_is_not(tmp_path, bin_dir):
    python = str(bin_dir / "python3")
    ours = planned([python, "-m", "launcher.packages.entry", "launcher.nodes.renderer:main"],
                   env_for(bin_dir), str(tmp_path), sys.executable)
    theirs = planned([python, "-m", "launcher.packages.entry", "my_pkg.talker:main"],
                     env_for(bin_dir), str(tmp_path), sys.executable)
    assert own_module(ours) == ("launcher.nodes.renderer",)
    assert own_module(theirs) == ()
