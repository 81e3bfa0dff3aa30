"""How `launcher launch` ends besides its processes (cli/launch_stops.py): the names a process
answers `--until` to, the sim's report read back, and the words of each ending."""

from __future__ import annotations

import json

import pytest

from launcher.arguments import Parser
from launcher.cli import launch_command
from launcher.cli.launch_stops import (
    UntilStop,
    duration_stop,
    never_started,
    sim_duration_stop,
    stopped_at_its_time,
)
from launcher.description.actions.shutdown import Shutdown
from launcher.description.substitution import perform_text
from launcher.errors import UsageError
from launcher.runtime import events
from launcher.runtime.context import LaunchContext
from launcher.runtime.control import label_base, names_of


def parse(*words: str):
    parser = Parser(prog="launcher launch")
    launch_command.add_arguments(parser)
    return parser.parse_args(["robot.launch.yaml", *words])


# --- the command line ----------------------------------------------------------------------
@pytest.mark.parametrize("value", ["0", "-1", "x", "nan", "inf"])
def test_a_sim_duration_must_be_a_number_above_0(value):
    with pytest.raises(UsageError, match=rf"argument --sim-duration: expected a number.*, "
                                         rf"got '{value}'"):
        parse("--sim-duration", value)


def test_the_sim_duration_and_until_are_read():
    args = parse("--sim-duration", "2.5", "--until", "driver", "--duration", "9")
    assert (args.sim_duration, args.until, args.duration) == (2.5, "driver", 9.0)


def test_a_negative_duration_is_refused_with_what_it_takes():
    with pytest.raises(UsageError, match="--duration: expected a number ≥ 0, got -1"):
        duration_stop(-1)


# --- --sim-duration ------------------------------------------------------------------------
def test_the_sim_duration_tells_the_children_their_stop_and_the_log_folders_sim(tmp_path):
    environment: dict[str, str] = {}
    sim_duration_stop(2.5, environment, tmp_path)
    assert environment == {"LAUNCHER_SIM_STOP_AT": "2.5",
                           "LAUNCHER_SIM_REPORT_DIR": str(tmp_path / "sim")}


def test_the_users_own_stop_and_report_folder_are_kept(tmp_path):
    environment = {"LAUNCHER_SIM_STOP_AT": "7", "LAUNCHER_SIM_REPORT_DIR": "/elsewhere"}
    sim_duration_stop(2.5, environment, tmp_path)
    assert environment == {"LAUNCHER_SIM_STOP_AT": "7", "LAUNCHER_SIM_REPORT_DIR": "/elsewhere"}


@pytest.mark.parametrize(("text", "stopped"), [
    (json.dumps({"stopped": True, "sim_time": 2.0}), True),
    (json.dumps({"stopped": False, "sim_time": 1.2}), False),
    ('{"stopped": tr', False),  # (half written: not a stop)
    ("[true]", False),
], ids=["stopped", "ended-otherwise", "half-written", "not-a-report"])
def test_a_report_says_whether_its_sim_stopped_at_its_time(tmp_path, text, stopped):
    (tmp_path / "sim-42.json").write_text(text)
    assert stopped_at_its_time(tmp_path, 42) is stopped


def test_a_process_without_a_report_did_not_stop_a_sim(tmp_path):
    (tmp_path / "sim-42.json").write_text(json.dumps({"stopped": True}))
    assert not stopped_at_its_time(tmp_path, 43)
    assert not stopped_at_its_time(tmp_path, None)


# --- --until -------------------------------------------------------------------------------
@pytest.mark.parametrize(("label", "base"), [("driver-3", "driver"), ("cam-2-15", "cam-2"),
                                             ("my_node", "my_node"), ("v2", "v2")])
def test_a_label_loses_the_number_the_launch_gave_it(label, base):
    assert label_base(label) == base


def test_a_process_goes_by_its_label_node_name_executable_and_programs_file_name():
    names = names_of("drive-4", ["/opt/bin/diff_drive", "--ros-args"], "/robot/drive",
                     "diff_drive")
    assert names == ["drive", "diff_drive"]
    assert names_of("driver-1", ["/usr/bin/python3", "-m", "x"], "/ns/pilot", "driver") == \
        ["driver", "pilot", "python3"]


def test_a_process_of_no_node_goes_by_its_label_and_program():
    assert names_of("sleep-2", ["sleep", "30"]) == ["sleep"]
    assert names_of("waiter-1", ["/bin/sh", "-c", "exit 3"]) == ["waiter", "sh"]


def exited(label: str, argv: list[str], code: int | None) -> events.ProcessExited:
    return events.ProcessExited(action=None, name=label, cmd=argv, cwd=None, env=None, pid=7,
                                returncode=code)


def test_the_exit_of_the_process_named_ends_the_launch_with_its_code():
    until, context = UntilStop("driver"), LaunchContext({})
    (shutdown,) = until.on_exit(exited("driver-2", ["sh", "-c", "exit 3"], 3), context)
    assert isinstance(shutdown, Shutdown)
    assert perform_text(context, shutdown.reason) == "--until driver: it exited with code 3"


def test_the_exit_of_another_process_does_not():
    until = UntilStop("driver")
    assert until.on_exit(exited("sleep-1", ["sleep", "1"], 0), LaunchContext({})) is None


def test_a_name_never_started_is_said_with_the_nearest_and_those_that_did():
    assert never_started("drvier", [["a"], ["driver", "python3"], ["c"], ["a"]]) == (
        "--until drvier: no process of that name started (did you mean 'driver'?); it "
        "started: a, driver, c")
    assert never_started("x", []) == "--until x: no process of that name started; it " \
                                     "started: none"


def test_the_end_of_a_launch_without_the_process_named_is_an_error():
    until = UntilStop("drvier")
    until.started = [["driver", "python3"], ["sleep"]]
    with pytest.raises(UsageError, match=r"no process of that name started \(did you mean "
                                         r"'driver'\?\); it started: driver, sleep"):
        until.check(0)


def test_the_end_of_a_launch_with_the_process_named_is_not():
    until = UntilStop("sleep")
    until.started = [["driver", "python3"], ["sleep"]]
    until.check(1)


def test_a_launch_a_signal_ended_is_not_an_error_of_the_name():
    UntilStop("drvier").check(130)
