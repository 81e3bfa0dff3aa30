"""A job on its node: its command line and environment, its status from what it left, and
its folder packed for the way back."""

from __future__ import annotations

import io
import os
import tarfile
import time
from pathlib import Path

import pytest

from launcher.batch import archive
from launcher.batch.job import JobFolder, JobSpec, command, environment
from launcher.batch.outcome import Ending, judge
from launcher.batch.results import Status


def spec(**fields) -> JobSpec:
    base = {"batch": "demo", "id": "abc", "title": "t[seed=3]", "kind": "test",
            "file": "test/drive_test.py", "arguments": {"world": "a.sdf"}, "seed": 3,
            "timeout": 60.0}
    return JobSpec(**{**base, **fields})


def test_a_launch_test_runs_as_launcher_test_with_its_arguments(tmp_path):
    argv = command(spec(), JobFolder(tmp_path), "py", Path("/ws"))
    assert argv == ["py", "-m", "launcher", "test", "/ws/test/drive_test.py", "world:=a.sdf",
                    "--package-name", "demo", "--junit-xml", str(tmp_path / "junit.xml")]


def test_a_launch_job_gets_its_end(tmp_path):
    argv = command(spec(kind="launch", file="r.launch.yaml", stop={"sim_duration": 30}),
                   JobFolder(tmp_path), "py", Path("/ws"))
    assert argv[-3:] == ["--noninteractive", "--sim-duration", "30"]


def test_a_packaged_launch_file_is_found_by_its_package(tmp_path):
    argv = command(spec(kind="launch", file="robot.launch.py", package="bringup",
                        stop={"until": "driver"}), JobFolder(tmp_path), "py", Path("/ws"))
    assert argv[3:7] == ["launch", "bringup", "robot.launch.py", "world:=a.sdf"]


def test_the_job_has_a_graph_and_folders_of_its_own(tmp_path):
    env = environment(spec(), {"LAUNCHER_RUN_DIR": "/theirs", "LAUNCHER_ROUTER": "tcp/x",
                               "RAY_ADDRESS": "a", "HOME": "/h"},
                      JobFolder(tmp_path), "/run/g", Path("/ws"), "LAUNCHER_BATCH_JOB_1")
    assert env["LAUNCHER_RUN_DIR"] == "/run/g" and "LAUNCHER_ROUTER" not in env
    assert "RAY_ADDRESS" not in env and env["HOME"] == "/h"
    assert env["ROS_LOG_DIR"] == str(tmp_path / "log")
    assert env["LAUNCHER_BATCH_JOB_1"] == "1"


def test_the_job_sees_its_seed(tmp_path):
    env = environment(spec(), {}, JobFolder(tmp_path), "/g", Path("/ws"), "M")
    assert env["LAUNCHER_BATCH_SEED"] == env["LAUNCHER_SIM_SEED"] == "3"


def test_lockstep_fixes_the_hash_order(tmp_path):
    env = environment(spec(lockstep=True), {}, JobFolder(tmp_path), "/g", Path("/ws"), "M")
    assert (env["LAUNCHER_SIM_LOCKSTEP"], env["PYTHONHASHSEED"]) == ("true", "0")


def test_the_batchs_package_path_comes_first(tmp_path):
    env = environment(spec(package_path=["src"]), {"LAUNCHER_PACKAGE_PATH": "/mine"},
                      JobFolder(tmp_path), "/g", Path("/ws"), "M")
    assert env["LAUNCHER_PACKAGE_PATH"] == "/ws/src:/mine"


def test_a_spec_travels_as_json():
    assert JobSpec.from_json(spec(stop={"until": "x"}).to_json()) == spec(stop={"until": "x"})


JUNIT = """<testsuites><testsuite name="t">
<testcase name="test_drives"/>{more}</testsuite></testsuites>"""


def folder_with(tmp_path: Path, junit: str | None = None, console: str = "") -> JobFolder:
    folder = JobFolder(tmp_path)
    folder.make()
    if junit is not None:
        folder.junit.write_text(junit)
    folder.console.write_text(console)
    return folder


def ending(code: int = 0, stopped: str | None = None) -> Ending:
    return Ending(code, stopped, 1.5, 0.0, [])


def test_a_test_that_passed(tmp_path):
    result = judge(spec(), folder_with(tmp_path, JUNIT.format(more="")), ending())
    assert result.status is Status.PASS and result.cases[0]["name"] == "test_drives"


def test_a_failed_case_names_itself(tmp_path):
    junit = JUNIT.format(more='<testcase name="test_stops"><failure message="it did not stop'
                              '"/></testcase>')
    result = judge(spec(), folder_with(tmp_path, junit), ending(1))
    assert (result.status, result.reason) == (Status.FAIL, "test_stops: it did not stop")


def test_a_test_that_could_not_run_is_an_error_with_launchers_words(tmp_path):
    folder = folder_with(tmp_path, console="error: t.py:3:1: bad launch file\n")
    result = judge(spec(), folder, ending(1))
    assert (result.status, result.reason) == (Status.ERROR, "t.py:3:1: bad launch file")


def test_a_launch_that_fails_as_it_runs_is_an_error_with_its_first_error(tmp_path):
    folder = folder_with(tmp_path, console="[ERROR] [launch]: x.yaml:3:1: package 'p' not "
                                           "found\n[INFO] [gz-1]: process stopped\n")
    result = judge(spec(kind="launch"), folder, ending(1))
    assert (result.status, result.reason) == (Status.ERROR,
                                              "x.yaml:3:1: package 'p' not found")


def test_a_test_file_with_no_test_is_an_error(tmp_path):
    result = judge(spec(), folder_with(tmp_path), ending(0))
    assert result.status is Status.ERROR and "no test ran" in result.reason


def test_a_launch_job_that_ended_cleanly_passed(tmp_path):
    assert judge(spec(kind="launch"), folder_with(tmp_path), ending()).status is Status.PASS


def test_a_launch_job_whose_process_failed_says_its_last_line(tmp_path):
    folder = folder_with(tmp_path, console="[ERROR] [driver-1]: process has died [exit 3]\n")
    result = judge(spec(kind="launch"), folder, ending(1))
    assert (result.status, result.reason) == (Status.FAIL,
                                              "[ERROR] [driver-1]: process has died [exit 3]")


def test_a_job_past_its_time_limit(tmp_path):
    result = judge(spec(), folder_with(tmp_path), ending(-2, "timeout"))
    assert (result.status, result.reason) == (Status.TIMEOUT, "ran past its time limit of "
                                                              "60 s; stopped")


def test_a_cancelled_job(tmp_path):
    assert judge(spec(), folder_with(tmp_path), ending(-2, "cancelled")).status is \
        Status.CANCELLED


def test_a_job_whose_worker_was_lost_is_an_error(tmp_path):
    result = judge(spec(), folder_with(tmp_path), ending(-2, "lost"))
    assert (result.status, result.reason) == (Status.ERROR, "stopped: lost")


def test_the_sims_report_gives_the_figures(tmp_path):
    folder = folder_with(tmp_path, JUNIT.format(more=""))
    (folder.sim / "sim-12.json").write_text(
        '{"sim_time": 120.0, "rtf": 11.5, "state": "0123456789abcdef"}')
    result = judge(spec(), folder, ending())
    assert (result.sim_s, result.rtf, result.state) == (120.0, 11.5, "0123456789abcdef")


def test_a_folder_packs_and_unpacks(tmp_path):
    (tmp_path / "job" / "log").mkdir(parents=True)
    (tmp_path / "job" / "log" / "launch.log").write_text("hello\n")
    packed = archive.pack(tmp_path / "job")
    archive.unpack(packed.read_bytes(), tmp_path / "back")
    packed.unlink()
    assert (tmp_path / "back" / "log" / "launch.log").read_text() == "hello\n"


def test_a_large_log_keeps_its_end(tmp_path, monkeypatch):
    monkeypatch.setattr(archive, "PER_FILE", 10)
    (tmp_path / "job").mkdir()
    (tmp_path / "job" / "output.log").write_text("0123456789abcdefghij")
    packed = archive.pack(tmp_path / "job")
    archive.unpack(packed.read_bytes(), tmp_path / "back")
    packed.unlink()
    assert (tmp_path / "back" / "output.log").read_text() == \
        "[the first 10 bytes were left out]\nabcdefghij"


def packed_member(name: str) -> bytes:
    data = io.BytesIO()
    with tarfile.open(fileobj=data, mode="w:gz") as tar:
        info = tarfile.TarInfo(name)
        info.size = 1
        tar.addfile(info, io.BytesIO(b"x"))
    return data.getvalue()


def test_an_archive_cannot_write_above_its_folder(tmp_path):
    with pytest.raises(tarfile.TarError):
        archive.unpack(packed_member("../outside"), tmp_path / "in")
    assert not (tmp_path / "outside").exists()


def test_an_absolute_member_lands_inside_the_folder(tmp_path):
    archive.unpack(packed_member("/etc/outside"), tmp_path / "in")
    assert (tmp_path / "in" / "etc" / "outside").read_bytes() == b"x"


def test_a_node_with_another_launcher_says_so_and_runs_nothing():
    from launcher.batch.task import run_job

    told = run_job(spec(launcher_version="0.0.1").to_json())
    assert told["setup"] and "runs launcher" in told["result"]["reason"]
    assert "install the same launcher[cluster] on every node" in told["result"]["reason"]


def test_a_shared_workspace_missing_on_a_node_says_so(tmp_path):
    from launcher import __version__
    from launcher.batch.task import run_job

    told = run_job(spec(root=str(tmp_path / "nowhere"), launcher_version=__version__).to_json())
    assert told["setup"] and f"the workspace is not at {tmp_path / 'nowhere'} there" in \
        told["result"]["reason"]


def test_without_tarfiles_data_filter_the_same_checks_hold(tmp_path, monkeypatch):
    """Python before 3.11.4 (Debian 12's 3.11.2) has no "data" filter."""
    monkeypatch.delattr(tarfile, "data_filter", raising=False)
    with pytest.raises(tarfile.TarError):
        archive.unpack(packed_member("../outside"), tmp_path / "in")
    archive.unpack(packed_member("/etc/outside"), tmp_path / "in")
    assert (tmp_path / "in" / "etc" / "outside").read_bytes() == b"x"
    assert not (tmp_path / "outside").exists()


def test_a_clusters_folder_whose_batch_is_gone_is_removed_by_the_next(tmp_path):
    from launcher.batch.cluster import PRIVATE_PREFIX
    from launcher.batch.job import OWNER, sweep_stale

    gone, running = tmp_path / f"{PRIVATE_PREFIX}a", tmp_path / f"{PRIVATE_PREFIX}b"
    for folder, pid in ((gone, 2**22 + 1), (running, os.getpid())):  # (above pid_max: gone)
        folder.mkdir()
        (folder / OWNER).write_text(str(pid))
    assert sweep_stale(tmp_path, PRIVATE_PREFIX) == [gone]
    assert running.exists() and not gone.exists()


def test_a_task_folder_that_lost_its_owner_file_is_removed_once_it_is_old(tmp_path):
    """A removal cut short (the job still wrote in it) leaves a folder without OWNER: the
    next task removes it once it is ORPHANED seconds old, and leaves a younger one be."""
    from launcher.batch.job import ORPHANED, SCRATCH_PREFIX, sweep_stale

    old, young = tmp_path / f"{SCRATCH_PREFIX}old", tmp_path / f"{SCRATCH_PREFIX}young"
    for folder in (old, young):
        (folder / "lnb-job").mkdir(parents=True)
    then = time.time() - ORPHANED - 60
    os.utime(old, (then, then))
    assert sweep_stale(tmp_path, SCRATCH_PREFIX) == [old]
    assert young.exists() and not old.exists()
