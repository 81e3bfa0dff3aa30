"""The sim's stop time and report (LAUNCHER_SIM_STOP_AT, LAUNCHER_SIM_REPORT_DIR,
LAUNCHER_SIM_SEED), and the launches they end: `launcher launch --sim-duration` and `--until`.
Real processes: the sim on a small world of falling bodies, unpaced, and shell commands."""

from __future__ import annotations

import json
import signal
import subprocess
import time

import pytest

from tests.support.processes import launcher_argv

TIMESTEP = 0.002
# a ball dropped and a box dropped tilted onto a floor: contacts by 2 s, nothing at rest
WORLD = f"""
<mujoco model="drop">
  <option timestep="{TIMESTEP}"/>
  <worldbody>
    <geom type="plane" size="5 5 0.1"/>
    <body name="ball" pos="0 0 1"><freejoint/><geom type="sphere" size="0.1" mass="1"/></body>
    <body name="box" pos="0.5 0 0.5" euler="10 20 30">
      <freejoint/><geom type="box" size="0.1 0.2 0.05" mass="1"/>
    </body>
  </worldbody>
</mujoco>
"""

SIM_LAUNCH = """
launch:
  - executable: {cmd: launcher sim -r -z 0 world.xml, name: sim}
"""


@pytest.fixture
def world(ws):
    ws.own_bus()
    ws.write("world.xml", WORLD)
    ws.write("sim.launch.yaml", SIM_LAUNCH)
    return ws


def reports(ws) -> list[dict]:
    """The reports of the latest launch's sims."""
    return [json.loads(path.read_text())
            for path in sorted((ws.root / "log" / "latest" / "sim").glob("sim-*.json"))]


def run_sim(ws, *words: str, **env: str) -> subprocess.CompletedProcess:
    return subprocess.run([*launcher_argv(), "sim", *words], cwd=ws.root,
                          env={**ws.env, **env}, capture_output=True, text=True, timeout=60)


# --- launcher launch --sim-duration ---------------------------------------------------------
def test_a_launch_runs_to_its_sim_duration_and_ends_cleanly(world):
    done = world.run("launch", "sim.launch.yaml", "--sim-duration", "2", "-n")
    assert done.returncode == 0, done.stdout + done.stderr
    assert "shutting down: --sim-duration 2 s of sim time reached" in done.stdout
    (report,) = reports(world)
    assert report["stopped"] is True
    assert 2 <= report["sim_time"] < 2 + TIMESTEP and report["steps"] == 1000
    assert report["world"] == str(world.root / "world.xml")
    assert report["lockstep_tick"] is None and report["seed"] == 0
    assert report["rtf"] == pytest.approx(report["sim_time"] / report["stepping_wall_s"])
    assert len(report["state"]) == 16 and int(report["state"], 16) >= 0


def test_the_same_world_stopped_at_the_same_time_reaches_the_same_state(world):
    states = []
    for _ in range(3):
        done = world.run("launch", "sim.launch.yaml", "--sim-duration", "1.5", "-n")
        assert done.returncode == 0, done.stdout + done.stderr
        states.append(reports(world)[0]["state"])
    assert len(set(states)) == 1, states


def test_a_sim_duration_without_a_sim_ends_when_the_processes_do(world):
    world.write("nosim.launch.yaml", "launch:\n  - executable: {cmd: sh -c 'sleep 0.2'}\n")
    done = world.run("launch", "nosim.launch.yaml", "--sim-duration", "30", "-n", timeout=30)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "--sim-duration" not in done.stdout


# --- the sim's own variables ----------------------------------------------------------------
@pytest.mark.parametrize(("words", "seed"), [((), 7), (("--seed", "3"), 3)],
                         ids=["from-the-variable", "the-flag-wins"])
def test_the_seed_variable_is_the_seeds_default(world, words, seed):
    done = run_sim(world, "-r", "-z", "0", *words, "world.xml", LAUNCHER_SIM_SEED="7",
                   LAUNCHER_SIM_STOP_AT="0.1", LAUNCHER_SIM_REPORT_DIR=str(world.root / "r"))
    assert done.returncode == 0, done.stderr
    (path,) = (world.root / "r").glob("sim-*.json")
    assert json.loads(path.read_text())["seed"] == seed


def test_a_sim_stopped_by_a_signal_reports_that_it_did_not_reach_its_stop(world):
    folder = world.root / "r"
    sim = world.start("sim", "-r", "-v", "3", "world.xml",
                      env={"LAUNCHER_SIM_REPORT_DIR": str(folder)})
    try:
        world.wait_for_output("world 'drop' from")
        time.sleep(0.5)  # (stepping, in real time)
        sim.send_signal(signal.SIGINT)
        assert sim.wait(30) == 0, world.output("stderr.txt")
    finally:
        sim.kill()
        sim.wait()
    report = json.loads((folder / f"sim-{sim.pid}.json").read_text())
    assert report["stopped"] is False and report["steps"] > 0
    assert report["sim_time"] == pytest.approx(report["steps"] * TIMESTEP)


@pytest.mark.parametrize(("name", "value", "expected"), [
    ("LAUNCHER_SIM_STOP_AT", "abc", "LAUNCHER_SIM_STOP_AT='abc': expected seconds of sim time "
                                    "(> 0)"),
    ("LAUNCHER_SIM_STOP_AT", "0", "LAUNCHER_SIM_STOP_AT='0': expected seconds of sim time (> 0)"),
    ("LAUNCHER_SIM_SEED", "abc", "LAUNCHER_SIM_SEED='abc': expected an integer seed (as --seed)"),
], ids=["stop-at-not-a-number", "stop-at-0", "seed-not-an-integer"])
def test_a_bad_sim_variable_is_said_with_what_it_takes(ws, name, value, expected):
    done = run_sim(ws, "-s", **{name: value})
    assert done.returncode == 2 and expected in done.stderr, done.stderr


def test_a_report_folder_that_cannot_be_made_is_said_at_the_start(ws):
    (ws.root / "file").write_text("")
    done = run_sim(ws, "-s", LAUNCHER_SIM_REPORT_DIR=str(ws.root / "file" / "r"))
    assert done.returncode == 2
    assert f"LAUNCHER_SIM_REPORT_DIR='{ws.root / 'file' / 'r'}': cannot make the folder" \
        in done.stderr


# --- launcher launch --until ----------------------------------------------------------------
UNTIL_LAUNCH = """
launch:
  - executable: {{cmd: "sh -c 'sleep 0.3; exit {code}'", name: driver}}
  - executable: {{cmd: sleep 30}}
"""


@pytest.mark.parametrize(("code", "status"), [(3, 1), (0, 0)], ids=["failed", "passed"])
def test_until_ends_the_launch_with_that_processs_status(ws, code, status):
    ws.write("until.launch.yaml", UNTIL_LAUNCH.format(code=code))
    done = ws.run("launch", "until.launch.yaml", "--until", "driver", "-n", timeout=30)
    assert done.returncode == status, done.stdout + done.stderr
    assert f"shutting down: --until driver: it exited with code {code}" in done.stdout


def test_until_a_process_never_started_is_an_error_at_the_end(ws):
    ws.write("until.launch.yaml", UNTIL_LAUNCH.format(code=0))
    done = ws.run("launch", "until.launch.yaml", "--until", "drvier", "--duration", "1", "-n",
                  timeout=30)
    assert done.returncode == 2
    assert "error: --until drvier: no process of that name started (did you mean 'driver'?); " \
           "it started: driver, sleep" in done.stderr
