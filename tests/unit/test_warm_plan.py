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


def ours(bin_dir) -> str:
    """launcher's interpreter, as these tests have it: bin_dir's python3."""
    return str(bin_dir / "python3")


def env_for(bin_dir) -> dict[str, str]:
    return {"PATH": f"{bin_dir}:/usr/bin:/bin"}


def executable(path, text: str) -> str:
    path.write_text(text)
    path.chmod(0o755)
    return str(path)


def test_a_script_run_through_env_is_shown_as_env_runs_it(tmp_path, bin_dir):
    script = executable(tmp_path / "node.py", "#!/usr/bin/env python3\nprint(1)\n")
    plan = planned([script, "a"], env_for(bin_dir), str(tmp_path), ours(bin_dir))
    assert plan is not None and (plan.run, plan.target, plan.argv) == ("script", script, ["a"])
    assert (plan.shown, plan.comm) == (["python3", script, "a"], "python3")


def test_a_script_naming_its_interpreter_is_named_as_the_script(tmp_path, bin_dir):
    """The kernel runs `#!/path/python3` itself: the process's name is the script's."""
    python = bin_dir / "python3"
    script = executable(tmp_path / "my_node", f"#!{python}\nprint(1)\n")
    plan = planned([script], env_for(bin_dir), str(tmp_path), ours(bin_dir))
    assert plan is not None and (plan.shown, plan.comm) == ([str(python), script], "my_node")


def test_a_script_found_on_path_is_given_to_its_interpreter_whole(tmp_path, bin_dir):
    executable(bin_dir / "my_node", "#!/usr/bin/env python3\nprint(1)\n")
    plan = planned(["my_node"], env_for(bin_dir), str(tmp_path), ours(bin_dir))
    assert plan is not None and plan.shown == ["python3", str(bin_dir / "my_node")]


@pytest.mark.parametrize("line", ["#!python3", "#!/usr/bin/env python3\r", "#!/usr/bin/env -S python3"],
                         ids=["relative", "carriage return", "options"])
def test_a_shebang_the_kernel_would_not_run_as_written_starts_cold(tmp_path, bin_dir, line):
    script = executable(tmp_path / "node.py", f"{line}\nprint(1)\n")
    assert planned([script], env_for(bin_dir), str(tmp_path), ours(bin_dir)) is None


def test_the_same_python_from_another_folder_starts_cold(tmp_path, bin_dir):
    """A venv's python and the system's are one file, but each finds its own packages."""
    other = tmp_path / "other"
    other.mkdir()
    (other / "python3").symlink_to(PYTHON)
    script = executable(tmp_path / "node.py", f"#!{other / 'python3'}\nprint(1)\n")
    assert planned([script], env_for(bin_dir), str(tmp_path), ours(bin_dir)) is None


def test_a_zip_application_starts_cold(tmp_path, bin_dir):
    (tmp_path / "app.pyz").write_bytes(b"PK\x03\x04rest")
    assert planned([str(bin_dir / "python3"), "app.pyz"], env_for(bin_dir), str(tmp_path),
                   ours(bin_dir)) is None


def test_a_script_for_another_python_starts_cold(tmp_path, bin_dir):
    script = executable(tmp_path / "node.py", "#!/opt/other/python3\nprint(1)\n")
    assert planned([script], env_for(bin_dir), str(tmp_path), ours(bin_dir)) is None


def test_interpreter_options_start_cold(tmp_path, bin_dir):
    executable(tmp_path / "node.py", "print(1)\n")
    assert planned([str(bin_dir / "python3"), "-u", "node.py"], env_for(bin_dir),
                   str(tmp_path), ours(bin_dir)) is None


def test_a_module_run_is_taken_with_its_arguments(tmp_path, bin_dir):
    plan = planned([str(bin_dir / "python3"), "-m", "pkg.mod", "x"], env_for(bin_dir),
                   str(tmp_path), ours(bin_dir))
    assert plan is not None and (plan.run, plan.target, plan.argv) == ("module", "pkg.mod",
                                                                      ["x"])


def test_a_missing_working_directory_starts_cold(tmp_path, bin_dir):
    script = executable(tmp_path / "node.py", "#!/usr/bin/env python3\n")
    assert planned([script], env_for(bin_dir), str(tmp_path / "gone"),
                   ours(bin_dir)) is None


def test_turned_off_every_process_starts_cold(tmp_path, bin_dir):
    script = executable(tmp_path / "node.py", "#!/usr/bin/env python3\n")
    env = {**env_for(bin_dir), "LAUNCHER_WARM_START": "0"}
    assert planned([script], env, str(tmp_path), ours(bin_dir)) is None


def test_launchers_own_node_is_imported_by_its_server_a_users_is_not(tmp_path, bin_dir):
    python = str(bin_dir / "python3")
    own = planned([python, "-m", "launcher.packages.entry", "launcher.nodes.renderer:main"],
                  env_for(bin_dir), str(tmp_path), python)
    theirs = planned([python, "-m", "launcher.packages.entry", "my_pkg.talker:main"],
                     env_for(bin_dir), str(tmp_path), python)
    assert own_module(own) == ("launcher.nodes.renderer",)
    assert own_module(theirs) == ()
