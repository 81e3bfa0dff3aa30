"""The user's hand on a running launch (runtime/control.py) replayed on the fakes of the
supervision history: stop, start and restart of one process, the refusals, the rows `launcher
ps` shows, the latest lines `launcher logs` reads, the figures and the log files' rotation."""

from __future__ import annotations

import os
import re
from pathlib import Path

import pytest

from launcher.runtime import events
from launcher.runtime.control import ProcessControl, Refused
from launcher.runtime.custody import Custody
from launcher.runtime.figures import Figures, groups
from launcher.runtime.logs import LogFile
from launcher.runtime.output import Printer
from launcher.runtime.process import ProcessSpec, State
from launcher.runtime.process_table import ProcessTable
from launcher.runtime.recent import Recent
from tests.support.fake_loop import FakeLoop
from tests.support.fake_system import FakeSystem


class Posting(FakeLoop):
    def open_posting(self) -> None:
        pass

    def call_soon(self, callback, *args):
        return self.call_later(0.0, callback, *args)


def launch(*specs: ProcessSpec, figures: Figures | None = None):
    loop, system, emitted, logs = Posting(), FakeSystem(), [], []
    recent = Recent(lines=3, size=1000)
    table = ProcessTable(loop, system, Custody(), Printer(color=False), None,  # type: ignore[arg-type]
                         lambda level, source, text: logs.append(text), emitted.append,
                         lambda: True, lambda: None, None, recent=recent)
    for spec in specs:
        table.start(spec)
    control = ProcessControl(table, loop, figures or Figures(None, read=dict), recent,  # type: ignore[arg-type]
                             lambda level, source, text: logs.append(text))
    return control, table, loop, system, emitted, logs


def spec(label: str, **fields) -> ProcessSpec:
    return ProcessSpec(label=label, argv=[f"/usr/bin/{label.split('-')[0]}"], env={}, **fields)


def test_a_stop_by_the_user_is_no_exit_for_the_handlers_and_no_respawn():
    control, table, loop, system, emitted, _ = launch(spec("talker-1", respawn=True))
    process = table.processes[0]
    assert control.act("stop", "talker-1", os.getuid()) == "stopping talker-1"
    system.leader_exits(loop, process.pid, -2)
    loop.advance(10)
    assert process.state is State.EXITED and process.held
    assert not [e for e in emitted if isinstance(e, events.ProcessExited | events.ExecutionComplete)]
    assert len(system.spawned) == 1  # (no respawn)
    assert control.rows()[0].state == "stopped"


def test_a_held_process_keeps_the_launch_running_until_the_launch_stops():
    control, table, loop, system, _, _ = launch(spec("talker-1"))
    control.act("stop", "talker-1", os.getuid())
    system.leader_exits(loop, table.processes[0].pid, -2)
    assert table.working()
    table.stop()
    assert not table.working()


def test_start_after_a_stop_spawns_it_again_and_says_process_started():
    control, table, loop, system, emitted, _ = launch(spec("talker-1"))
    control.act("stop", "talker-1", os.getuid())
    system.leader_exits(loop, table.processes[0].pid, -2)
    said = control.act("start", "talker-1", os.getuid())
    assert said == f"started talker-1 (pid {system.spawned[-1]})"
    row = control.rows()[0]
    assert (row.state, row.restarts, row.pid) == ("running", 1, system.spawned[-1])
    assert sum(isinstance(e, events.ProcessStarted) for e in emitted) == 2


def test_restart_stops_with_its_signal_sequence_then_starts_once_its_group_is_gone():
    control, table, loop, system, _, _ = launch(spec("talker-1", sigterm_timeout=2.0))
    first = table.processes[0].pid
    control.act("restart", "talker-1", os.getuid())
    assert system.signals[-1] == (first, 2)
    loop.advance(2.1)
    assert system.signals[-1] == (first, 15)  # (its own timeout, then SIGTERM)
    system.leader_exits(loop, first, -15)
    loop.advance(0.1)
    assert len(system.spawned) == 2 and table.processes[0].state is State.RUNNING


@pytest.mark.parametrize(("verb", "name", "expected"), [
    ("start", "talker-1", "'talker-1' is already running"),
    ("restart", "tlaker-1", "this launch has no process 'tlaker-1' (did you mean 'talker-1'?)"),
    ("kill", "talker-1", "unknown verb 'kill'"),
])
def test_what_cannot_be_done_is_refused_and_nothing_changes(verb, name, expected):
    control, table, _, system, _, _ = launch(spec("talker-1"))
    with pytest.raises(Refused, match=re.escape(expected)):
        control.act(verb, name, os.getuid())
    assert system.signals == [] and len(system.spawned) == 1


def test_a_request_from_another_user_is_refused():
    control, _, _, system, _, _ = launch(spec("talker-1"))
    with pytest.raises(Refused, match="is not yours"):
        control.act("stop", "talker-1", os.getuid() + 1)
    assert system.signals == []


def test_stop_of_a_process_that_is_not_running_is_refused():
    control, table, loop, system, _, _ = launch(spec("talker-1"))
    system.leader_exits(loop, table.processes[0].pid, 0)
    with pytest.raises(Refused, match="'talker-1' is not running \\(it is exited\\)"):
        control.act("stop", "talker-1", os.getuid())


def test_the_rows_name_every_name_a_process_goes_by():
    control, *_ = launch(spec("talker-1", node_name="/robot/chatter"))
    row = control.rows()[0]
    assert row.names == ["talker-1", "talker", "chatter"]
    assert row.node == "/robot/chatter" and row.host == os.uname().nodename


def test_logs_keep_the_latest_lines_numbered_so_a_follower_gets_what_came_after():
    recent = Recent(lines=3, size=1000)
    for n in range(1, 6):
        recent.add("talker-1", "stdout", f"line {n}")
    first, lines = recent.after("talker-1", 0)
    assert first == 3 and [line.text for line in lines] == ["line 3", "line 4", "line 5"]
    assert [line.number for line in recent.after("talker-1", 4)[1]] == [5]


def test_logs_are_bounded_in_bytes_as_well_as_lines():
    recent = Recent(lines=100, size=10)
    for text in ("aaaa", "bbbb", "cccc"):
        recent.add("talker-1", "stdout", text)
    assert [line.text for line in recent.after("talker-1", 0)[1]] == ["bbbb", "cccc"]


def test_figures_are_cpu_per_second_and_memory_of_each_group():
    ticks = os.sysconf("SC_CLK_TCK")
    reads = iter([{100: (0, 10)}, {100: (ticks // 2, 20)}])
    clock = iter([1.0, 2.0])
    figures = Figures(None, read=lambda: next(reads), clock=lambda: next(clock))
    figures.sample([("talker-1", 100)])
    figures.sample([("talker-1", 100)])
    assert figures.now[100].cpu == pytest.approx(50.0, abs=1)
    assert figures.now[100].memory == 20 * os.sysconf("SC_PAGE_SIZE")


def test_figures_are_written_to_the_run_s_csv(tmp_path: Path):
    figures = Figures(tmp_path, read=lambda: {100: (5, 1)})
    figures.sample([("talker-1", 100)])
    figures.close()
    lines = (tmp_path / "processes.csv").read_text().splitlines()
    assert lines[0] == "time,name,pid,cpu_percent,rss_bytes"
    assert lines[1].split(",")[1:3] == ["talker-1", "100"]


def test_the_proc_reading_sums_each_group():
    table = groups()
    own = os.getpgid(0)
    assert own in table and table[own][1] > 0


def test_the_figures_file_rotates_as_the_logs_do_and_each_file_has_its_header(tmp_path):
    figures = Figures(tmp_path, limit=120, read=lambda: {100: (5, 1)})
    for _ in range(4):
        figures.sample([("talker-1", 100)])
    figures.close()
    for name in ("processes.csv", "processes.csv.1"):
        assert (tmp_path / name).read_text().startswith("time,name,pid,cpu_percent,rss_bytes\n")


def test_figures_keep_the_last_ones_when_proc_cannot_be_read():
    def unreadable():
        raise OSError(24, "Too many open files")

    figures = Figures(None, read=unreadable)
    figures.sample([("talker-1", 100)])
    assert figures.now == {}


def test_a_log_file_rotates_at_its_limit_keeping_lines_whole(tmp_path: Path):
    log = LogFile(tmp_path / "launch.log", limit=20)
    for n in range(7):
        log.write(f"line number {n}\n")  # 14 bytes: one a file
    log.close()
    assert (tmp_path / "launch.log").read_text() == "line number 6\n"
    assert (tmp_path / "launch.log.1").read_text() == "line number 5\n"
    assert not (tmp_path / "launch.log.6").exists()  # (five kept)


# --- picking a process by name across the running launches (bus/launches.py) ----------------
def listing(launch: str, pid: int, *rows: tuple[str, list[str]]):
    from types import SimpleNamespace

    from launcher.bus.launches import Launch

    processes = [SimpleNamespace(name=name, names=[name, *names], node="") for name, names in rows]
    return Launch(f"/launcher_{pid}", SimpleNamespace(launch=launch, pid=pid, file=launch,
                                                      processes=processes, message=""))


def launches_of(*running):
    from launcher.bus.launches import Launches

    launches = Launches.__new__(Launches)  # (no graph: the listing is given)
    launches.all = lambda: list(running)
    return launches


def test_a_name_that_two_processes_go_by_is_refused_with_both_named():
    from launcher.errors import LaunchError

    launches = launches_of(listing("a.launch.yaml", 10, ("talker-1", ["talker"])),
                           listing("b.launch.yaml", 20, ("talker-1", ["talker"])))
    with pytest.raises(LaunchError, match="'talker' names several processes: talker-1 "
                                          r"\(in a.launch.yaml \(pid 10\)\), talker-1 \(in "
                                          r"b.launch.yaml \(pid 20\)\).*--launch"):
        launches.pick("talker")


def test_launch_picks_one_of_several_by_its_file_or_pid():
    launches = launches_of(listing("a.launch.yaml", 10, ("talker-1", ["talker"])),
                           listing("b.launch.yaml", 20, ("talker-1", ["talker"])))
    assert launches.pick("talker", "b")[0].listing.pid == 20
    assert launches.pick("talker", "10")[0].listing.pid == 10


def test_an_unknown_launch_is_said_with_the_running_ones():
    from launcher.errors import LaunchError

    launches = launches_of(listing("robot.launch.yaml", 10, ("sim-1", ["sim"])))
    with pytest.raises(LaunchError, match=r"--launch robt: no running launch is 'robt' \(did "
                                          r"you mean 'robot'\?\); running: robot.launch.yaml"):
        launches.pick("sim", "robt")


def test_ps_says_why_a_launch_listed_no_processes():
    from types import SimpleNamespace

    from launcher.bus.launches import Launch
    from launcher.cli.ps_command import table

    ending = Launch("/_launcher_10", SimpleNamespace(
        launch="robot.launch.yaml", pid=10, uptime=5.0, log_folder="", processes=[],
        message="the launch is ending"))
    assert table([ending]).splitlines() == ["robot.launch.yaml  pid 10  up 0:00:05",
                                            "  (the launch is ending)"]


def test_a_name_not_found_says_which_launch_could_not_list_its_processes():
    from types import SimpleNamespace

    from launcher.bus.launches import Launch
    from launcher.errors import LaunchError

    busy = Launch("/_launcher_10", SimpleNamespace(
        launch="robot.launch.yaml", pid=10, file="robot.launch.yaml", processes=[],
        message="the launch did not answer within 5 s"))
    with pytest.raises(LaunchError, match=r"no process 'sim' in robot.launch.yaml \(pid 10\) "
                                          r"\(`launcher ps` lists them\); robot.launch.yaml "
                                          r"\(pid 10\) listed none: the launch did not answer "
                                          r"within 5 s"):
        launches_of(busy).pick("sim")
