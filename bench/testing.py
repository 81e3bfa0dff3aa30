#!/usr/bin/env python3
"""Launch tests (issue 41), each against its reference in the same run.

- `launch_test` of launch_testing's `hello_world_launch_test.py` and `good_proc_launch_test.py`
  (../shared/external, unchanged): wall time of launcher's against the real launch_testing
  (3.7.1, installed from source into the ROS 2 oracle venv that tests/fidelity/record.py
  makes, `.fidelity/ros2`); the ratio of medians (target ≤ 0.5). Without that venv, launcher's
  figure alone.
- 8 launch tests at once on this machine's cores (each on a graph of its own) against the same
  8 one by one: all pass, and the wall-time ratio.
- The demo in lockstep (launch_files/robot_lockstep.launch.yaml) driven 2 m in a launch test
  (bench/lockstep_launch_test.py): the sim time that took against the wall time (target ≥ 5×
  faster than real time).
"""

from __future__ import annotations

import os
import re
import statistics
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from _harness import launcher_cmd, table

REPO = Path(__file__).resolve().parent.parent
EXAMPLES = (REPO.parent / "shared/external/launch_testing/launch_testing/test/launch_testing/"
            "examples")
PROCESSES = EXAMPLES.parents[2] / "example_processes"
ORACLE = REPO / ".fidelity" / "ros2"
ROUNDS = 3
PARALLEL = 8


def prefix(root: Path) -> Path:
    """An install prefix of launch_testing holding its example processes (as its own has)."""
    packages = root / "share/ament_index/resource_index/packages"
    packages.mkdir(parents=True, exist_ok=True)
    (packages / "launch_testing").touch()
    (root / "lib/launch_testing").mkdir(parents=True, exist_ok=True)
    for script in PROCESSES.glob("*.py"):
        link = root / "lib/launch_testing" / script.name
        if not link.exists():
            link.symlink_to(script)
    return root


def timed(command: list[str], env: dict[str, str], cwd: Path) -> float:
    start = time.monotonic()
    done = subprocess.run(command, env=env, cwd=cwd, capture_output=True, text=True,
                          timeout=300)
    if done.returncode != 0:
        raise SystemExit(f"{' '.join(command)} failed:\n{done.stdout}{done.stderr}")
    return time.monotonic() - start


def ours(name: str, folder: Path) -> list[str]:
    return [*launcher_cmd(), "test", str(EXAMPLES / name)]


def real_env() -> dict[str, str]:
    return {"PATH": f"{ORACLE / 'bin'}:/usr/bin:/bin", "HOME": os.environ.get("HOME", "/"),
            "AMENT_PREFIX_PATH": str(ORACLE)}


def compare(name: str, folder: Path) -> tuple[str, str, str]:
    env = dict(os.environ, AMENT_PREFIX_PATH=str(prefix(folder / "prefix")),
               LAUNCHER_RUN_DIR=str(folder / "run"))
    mine = [timed(ours(name, folder), env, folder) for _ in range(ROUNDS)]
    if not (ORACLE / "bin/launch_test").exists():
        return (f"launch_test {name}", "≤ 0.5× real",
                f"{statistics.median(mine):.2f} s (no real launch_testing in {ORACLE})")
    real = [timed([str(ORACLE / "bin/launch_test"), str(EXAMPLES / name)], real_env(), folder)
            for _ in range(ROUNDS)]
    ratio = statistics.median(mine) / statistics.median(real)
    return (f"launch_test {name}", "≤ 0.5× real",
            f"{ratio:.2f}× ({statistics.median(mine):.2f} s against "
            f"{statistics.median(real):.2f} s)")


def parallel(folder: Path) -> tuple[str, str, str]:
    env = dict(os.environ, AMENT_PREFIX_PATH=str(prefix(folder / "prefix")))
    command = ours("good_proc_launch_test.py", folder)

    def one(index: int) -> float:
        return timed(command, dict(env, LAUNCHER_RUN_DIR=str(folder / f"run{index}")), folder)

    start = time.monotonic()
    for index in range(PARALLEL):
        one(index)
    serial = time.monotonic() - start
    start = time.monotonic()
    with ThreadPoolExecutor(PARALLEL) as pool:
        list(pool.map(one, range(PARALLEL)))
    together = time.monotonic() - start
    return (f"{PARALLEL} launch tests at once ({os.cpu_count()} cores)", "all pass",
            f"all pass; {together / serial:.2f} of one by one ({together:.1f} s against "
            f"{serial:.1f} s)")


def lockstep(folder: Path) -> tuple[str, str, str]:
    env = dict(os.environ, LAUNCHER_PACKAGE_PATH=str(REPO / "packages"),
               LAUNCHER_RUN_DIR=str(folder / "run-lockstep"))
    factors = []
    for _ in range(ROUNDS):
        done = subprocess.run([*launcher_cmd(), "test", str(REPO / "bench" /
                                                            "lockstep_launch_test.py")],
                              env=env, cwd=folder, capture_output=True, text=True, timeout=300)
        found = re.search(r"LOCKSTEP sim=([\d.]+) wall=([\d.]+)", done.stdout + done.stderr)
        if done.returncode != 0 or found is None:
            raise SystemExit(f"the lockstep launch test failed:\n{done.stdout}{done.stderr}")
        sim, wall = float(found.group(1)), float(found.group(2))
        factors.append((sim / wall, sim, wall))
    factor, sim, wall = sorted(factors)[len(factors) // 2]
    return ("demo in lockstep driven 2 m (launch test)", "≥ 5× real time",
            f"{factor:.1f}× ({sim:.2f} s of sim time in {wall:.2f} s)")


def main() -> None:
    if not EXAMPLES.is_dir():
        sys.exit(f"bench/testing.py needs {EXAMPLES}")
    with tempfile.TemporaryDirectory(prefix="bench-testing-") as name:
        folder = Path(name)
        rows = [compare("hello_world_launch_test.py", folder),
                compare("good_proc_launch_test.py", folder), parallel(folder),
                lockstep(folder)]
    table("launch tests (issue 41)", rows)


if __name__ == "__main__":
    main()
