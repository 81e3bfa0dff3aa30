"""Many scenarios at once: `launcher batch` on Ray, against the same jobs run one by one, in
the same run.

- 40 short launch tests (the demo driven 2 m in lockstep, bench/lockstep_launch_test.py, over
  4 worlds × 10 seeds, as launch_files/demo.batch.yaml has them): `launcher batch` on Ray
  started for the batch (its start counted) against `launcher test … world_name:=W` forty
  times in a row. The bound 2 cores allow is printed beside it: one job alone keeps C cores
  busy (the CPU time of the serial runs over their wall time), so two at once are at most 2/C
  times faster.
- Ray's overhead per job: 5 jobs, one at a time (each asks for both cores), the batch's time
  per job (Ray's start apart) against the job alone (median of 5).
- The same 20 jobs on a two-node Ray cluster (1 CPU a node, each node in a network namespace:
  tests/support/ray_cluster.py; needs root) against a one-node one (1 CPU).
- Jobs per hour, from the figures above.
"""

from __future__ import annotations

import contextlib
import json
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterator
from pathlib import Path

from _harness import launcher_cmd, table

REPO = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPO))

TEST = REPO / "bench" / "lockstep_launch_test.py"
WORLDS = ("robot.world", "world.sdf", "empty.sdf", "empty.xml")
SEEDS = 10
ALONE_RUNS = 5


def batch_file(folder: Path, worlds: tuple[str, ...], seeds: int, cpus: float,
               workspace: Path = REPO) -> Path:
    path = folder / "demo.batch.yaml"
    path.write_text(
        f"name: demo\nworkspace: {workspace}\npackage_path: [{REPO / 'packages'}]\n"
        f"jobs:\n  - test: {TEST}\n    name: drive\nmatrix:\n  world_name: {list(worlds)}\n"
        f"seeds: {seeds}\nlockstep: true\ntimeout: 120\nresources: {{cpus: {cpus}}}\n")
    return path


def run_batch(path: Path, results: Path) -> tuple[float, dict]:
    """(the command's wall time, its results.json)."""
    started = time.monotonic()
    done = subprocess.run(launcher_cmd() + ["batch", str(path), "-n", "--results",
                                            str(results)], capture_output=True, text=True,
                          timeout=1800)
    wall = time.monotonic() - started
    if done.returncode != 0:
        raise SystemExit(f"launcher batch failed:\n{done.stdout}\n{done.stderr}")
    return wall, json.loads((results / "latest" / "results.json").read_text())


def run_alone(world: str, seed: int) -> float:
    env = dict(os.environ, LAUNCHER_SIM_SEED=str(seed), LAUNCHER_BATCH_SEED=str(seed),
               LAUNCHER_SIM_LOCKSTEP="true", PYTHONHASHSEED="0",
               LAUNCHER_PACKAGE_PATH=str(REPO / "packages"))
    started = time.monotonic()
    done = subprocess.run(launcher_cmd() + ["test", str(TEST), f"world_name:={world}"],
                          capture_output=True, text=True, env=env, cwd=REPO, timeout=300)
    if done.returncode != 0:
        raise SystemExit(f"launcher test failed:\n{done.stdout}\n{done.stderr}")
    return time.monotonic() - started


def serial_and_batch(folder: Path) -> list[tuple[str, str, str]]:
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    serial = sum(run_alone(w, s) for s in range(SEEDS) for w in WORLDS)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    busy = (after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime) / serial
    wall, told = run_batch(batch_file(folder, WORLDS, SEEDS, 1), folder / "r40")
    passed = sum(j["status"] == "pass" for j in told["jobs"])
    jobs = len(told["jobs"])
    return [
        ("40 launch tests: batch vs one by one", "≥ 1.8×",
         f"{serial / wall:.2f}× ({wall:.1f} s against {serial:.1f} s; {passed}/{jobs} passed); "
         f"one job alone keeps {busy:.2f} of 2 cores busy, so 2 cores allow at most "
         f"{2 / busy:.2f}×"),
        ("jobs per hour, this machine", "reported",
         f"{3600 * jobs / wall:.0f} (Ray's start included), {3600 * jobs / told['wall_s']:.0f} "
         f"once started"),
    ]


def overhead(folder: Path) -> list[tuple[str, str, str]]:
    alone = statistics.median(run_alone("robot.world", s) for s in range(ALONE_RUNS))
    wall, told = run_batch(batch_file(folder, ("robot.world",), ALONE_RUNS, 2), folder / "r5")
    per_job = told["wall_s"] / ALONE_RUNS
    return [("Ray's overhead per job (one at a time)", "≤ +10%",
             f"{100 * (per_job / alone - 1):+.0f}% ({per_job:.2f} s a job in the batch "
             f"against {alone:.2f} s alone); Ray's start and end {wall - told['wall_s']:.1f} s "
             "once per batch")]


def on_clusters(folder: Path) -> list[tuple[str, str, str]]:
    from tests.support.ray_cluster import NodeSpec, RayCluster

    if os.geteuid() != 0:
        return [("20 jobs: 2 nodes vs 1", "reported", "not run: needs root (namespaces)")]
    walls = {}
    for nodes in ((NodeSpec("head", 1),), (NodeSpec("head", 1), NodeSpec("w1", 1))):
        root = Path(tempfile.mkdtemp(prefix="lnc", dir="/tmp"))  # (short: Ray's sockets)
        with RayCluster(root, nodes) as cluster, _removed(root):
            path = batch_file(folder, WORLDS, 5, 1)
            path.write_text(path.read_text() + "shared_workspace: true\n")  # (one machine)
            _, told = run_cluster(cluster, path, folder / f"c{len(nodes)}",
                                  cluster.driver_env(os.environ))
            walls[len(nodes)] = told["wall_s"]
    return [("20 jobs: 2 nodes vs 1 (1 CPU each)", "reported",
             f"{walls[1] / walls[2]:.2f}× ({walls[2]:.1f} s on 2 nodes, {walls[1]:.1f} s on 1); "
             f"{3600 * 20 / walls[1]:.0f} jobs/hour on one 1-CPU node")]


def run_cluster(cluster, path: Path, results: Path, env: dict[str, str]) -> tuple[float, dict]:
    argv = cluster.driver_argv(launcher_cmd() + ["batch", str(path), "-n", "--results",
                                                 str(results), "--address", cluster.address])
    started = time.monotonic()
    done = subprocess.run(argv, capture_output=True, text=True, env=env, timeout=1800)
    if done.returncode != 0:
        raise SystemExit(f"launcher batch failed:\n{done.stdout}\n{done.stderr}")
    return time.monotonic() - started, json.loads((results / "latest" /
                                                   "results.json").read_text())


@contextlib.contextmanager
def _removed(folder: Path) -> Iterator[None]:
    try:
        yield
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def main() -> None:
    folder = Path(tempfile.mkdtemp(prefix="launcher-bench-batch-"))
    os.environ["LAUNCHER_LOG_DIR"] = str(folder / "log")
    with _removed(folder):
        rows = serial_and_batch(folder) + overhead(folder) + on_clusters(folder)
    table("launcher batch (Ray): many scenarios at once", rows)


if __name__ == "__main__":
    main()
