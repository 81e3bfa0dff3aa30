"""The supervision state machine replayed through event histories: a fake loop whose clock
the test moves, and a recording fake of the operating system. No process is started; each
history runs in milliseconds (the real-process tests are in tests/integration)."""

from __future__ import annotations

import signal

import pytest

from launcher.runtime.process import (
    BACKOFF_CAP,
    STABLE,
    ManagedProcess,
    ProcessHooks,
    ProcessSpec,
    State,
)
from tests.support.fake_loop import FakeLoop
from tests.support.fake_system import FakeSystem


class Recorder:
    def __init__(self) -> None:
        self.logs: list[tuple[str, str]] = []
        self.exited: list[bool] = []
        self.lines: list[str] = []

    def hooks(self) -> ProcessHooks:
        return ProcessHooks(
            line=lambda process, record, targets: self.lines.append(record.text),
            started=lambda process: None,
            exited=lambda process, respawn: self.exited.append(respawn),
            log=lambda level, source, message: self.logs.append((level, message)),
            group=lambda pgid, alive: None)


def make(**spec_fields) -> tuple[ManagedProcess, FakeLoop, FakeSystem, Recorder]:
    loop, system, recorder = FakeLoop(), FakeSystem(spec_fields.pop("fail_spawns", 0)), \
        Recorder()
    spec = ProcessSpec(label="worker-1", argv=["worker"], env={}, **spec_fields)
    process = ManagedProcess(spec, recorder.hooks(), loop, system=system)  # type: ignore[arg-type]
    process.spawn()
    return process, loop, system, recorder


def test_a_clean_exit_ends_in_exited_and_says_so():
    process, loop, system, recorder = make()
    system.output[system.streams.stdout] += [b"hello\nwor", b"ld\n"]
    loop.ready(system.streams.stdout)
    loop.ready(system.streams.stdout)
    system.leader_exits(loop, 100, 0)
    assert process.state is State.EXITED and not process.failed
    assert recorder.lines == ["hello", "world"]
    assert recorder.logs[-1] == ("INFO", "process has finished cleanly [pid 100]")
    assert recorder.exited == [False]
    assert system.signals == [(100, signal.SIGKILL)]  # whatever it left: none here
    assert sorted(system.closed) == [10, 11]


def test_exiting_on_its_own_kills_what_it_left_in_its_group():
    process, loop, system, recorder = make()
    system.leader_exits(loop, 100, 3, group_empty=False)
    assert system.signals == [(100, signal.SIGKILL)]
    assert process.state is State.EXITED and process.failed
    assert "exited with code 3" in recorder.logs[-1][1]


def test_respawn_with_a_delay_and_a_limit_then_exited():
    process, loop, system, recorder = make(respawn=True, respawn_delay=1.0,
                                           respawn_max_retries=2)
    history = []
    for _ in range(3):
        loop.advance(STABLE)  # (each ran long enough: no back-off)
        system.leader_exits(loop, system.spawned[-1], 1)
        history.append(process.state)
        loop.advance(0.99)
        history.append(process.state)
        loop.advance(0.02)
    assert history == [State.BACKOFF, State.BACKOFF, State.BACKOFF, State.BACKOFF,
                       State.EXITED, State.EXITED]
    assert len(system.spawned) == 3 and process.respawns == 2 and process.failed
    messages = [m for _, m in recorder.logs]
    assert "respawning in 1 s (attempt 1 of 2)" in messages[0]
    assert "respawning in 1 s (attempt 2 of 2)" in messages[1]
    assert "not respawning: it was respawned 2 times, its respawn_max_retries" in messages[2]
    assert recorder.exited == [True, True, False]


def respawned(loop, system) -> float:
    """Move the clock until the next spawn; how long that took (in 0.01 s steps)."""
    began, before = loop.now, len(system.spawned)
    while len(system.spawned) == before:
        loop.advance(0.01)
    return loop.now - began


def test_a_respawn_storm_backs_off_doubling_up_to_its_cap_and_is_said_once():
    process, loop, system, recorder = make(respawn=True, respawn_delay=0.0)
    waits = []
    for _ in range(12):
        system.leader_exits(loop, system.spawned[-1], 1)  # at once: a storm
        waits.append(respawned(loop, system))
    # (its own 0 s twice, then 0.1 s doubling)
    assert waits[:7] == pytest.approx([0.0, 0.0, 0.1, 0.2, 0.4, 0.8, 1.6], abs=0.02)
    assert max(waits) == pytest.approx(BACKOFF_CAP, abs=0.02)
    said = [m for _, m in recorder.logs]
    assert len(said) == 3 and "within 5 s of its start 3 times in a row" in said[2]


def test_a_process_that_ran_its_stable_time_respawns_without_back_off_again():
    process, loop, system, recorder = make(respawn=True, respawn_delay=0.5)
    for _ in range(4):
        system.leader_exits(loop, system.spawned[-1], 1)
        respawned(loop, system)
    assert process.quick == 4
    loop.advance(STABLE)
    system.leader_exits(loop, system.spawned[-1], 1)
    assert process.quick == 0 and "respawning in 0.5 s" in recorder.logs[-1][1]


def test_stop_escalates_sigint_sigterm_sigkill_on_the_group_with_their_timeouts():
    process, loop, system, recorder = make(sigterm_timeout=5.0, sigkill_timeout=3.0)
    process.stop()
    process.stop()  # safe twice
    assert process.state is State.STOPPING and system.signals == [(100, signal.SIGINT)]
    loop.advance(4.9)
    assert system.signals == [(100, signal.SIGINT)]
    loop.advance(0.2)
    assert system.signals[-1] == (100, signal.SIGTERM)
    loop.advance(3.0)
    assert system.signals[-1] == (100, signal.SIGKILL)
    system.leader_exits(loop, 100, -signal.SIGKILL)
    assert process.state is State.EXITED
    assert recorder.logs[-1] == ("INFO", "process stopped: it was killed by SIGKILL [pid 100]")
    assert [m for level, m in recorder.logs if level == "WARN"] == [
        "still running; sending SIGTERM", "still running; sending SIGKILL"]


def test_a_stopped_leader_is_not_done_while_its_group_lives_on():
    process, loop, system, recorder = make()
    process.stop()
    system.leader_exits(loop, 100, -signal.SIGINT, group_empty=False)
    loop.advance(0.5)
    assert process.state is State.STOPPING  # a grandchild still holds the group
    system.group[100] = False
    loop.advance(0.05)
    assert process.state is State.EXITED
    assert not process.failed  # the launcher caused this exit


def test_escalate_sends_the_next_signal_at_once():
    process, loop, system, _ = make()
    process.stop()
    process.escalate()
    assert [sig for _, sig in system.signals] == [signal.SIGINT, signal.SIGTERM]


def test_stop_while_waiting_to_respawn_ends_without_spawning():
    process, loop, system, recorder = make(respawn=True, respawn_delay=2.0)
    system.leader_exits(loop, 100, 1)
    process.stop()
    loop.advance(5.0)
    assert process.state is State.EXITED and system.spawned == [100]
    assert recorder.exited == [True, False]


def test_a_respawn_that_cannot_spawn_is_fatal():
    process, loop, system, recorder = make(respawn=True, respawn_delay=0.5)
    system.fail_spawns = 1
    system.leader_exits(loop, 100, 1)
    loop.advance(0.5)
    assert process.state is State.FATAL
    assert recorder.logs[-1][0] == "ERROR" and "could not respawn" in recorder.logs[-1][1]


def test_the_state_machine_refuses_an_edge_it_does_not_have():
    process, loop, system, _ = make()
    with pytest.raises(RuntimeError, match="no transition RUNNING -> STARTING"):
        process._to(State.STARTING)


# --- the watchdog's last look (runtime/reaper.py) --------------------------------------------
def test_the_watchdog_skips_its_looks_when_the_launch_ended_clean(monkeypatch):
    from launcher.runtime import reaper

    looked = []
    monkeypatch.setattr(reaper.lineage, "marked", lambda mark: looked.append(mark) or set())
    monkeypatch.setattr(reaper.time, "sleep", lambda seconds: None)
    launch = reaper.Launch("MARK")
    for line in (b"+4000001", b"-4000001", b"="):  # a group that came and went, then the end
        launch.follow(line)
    launch.clean_up()
    assert looked == []
    unclean = reaper.Launch("MARK")  # no "=": a launcher that died; it looks until quiet
    unclean.follow(b"+4000001")
    unclean.clean_up()
    assert len(looked) == reaper.LOOKS


def test_the_watchdog_still_stops_a_group_it_was_told_of_after_a_clean_end(monkeypatch):
    from launcher.runtime import reaper

    alive = {4000002}
    killed = []

    def killpg(pgid, sig):
        killed.append((pgid, sig))
        alive.discard(pgid)

    monkeypatch.setattr(reaper, "group_alive", lambda pgid: pgid in alive)
    monkeypatch.setattr(reaper.lineage, "live_groups", lambda groups: set(groups))
    monkeypatch.setattr(reaper.lineage, "marked", lambda mark: set())
    monkeypatch.setattr(reaper.os, "killpg", killpg)
    monkeypatch.setattr(reaper.time, "sleep", lambda seconds: None)
    launch = reaper.Launch("MARK")
    launch.follow(b"+4000002")
    launch.follow(b"=")
    launch.clean_up()
    assert killed == [(4000002, signal.SIGTERM)]
