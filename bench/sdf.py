#!/usr/bin/env python3
"""SDF worlds (issue 12): loading gz-sim's shapes.sdf and diff_drive.sdf against the same
worlds written by hand in MJCF (bench/worlds/), and a generated world of 1,000 SDF models:
its load time, and MuJoCo's steps per second on it against the same world in MJCF.

Each figure is a ratio measured in the same run, the two sides interleaved, so the machine's
load falls on both alike. Load = file to compiled MjModel through the sim's one entry point
(launcher.sim.loading), as `gz sim` does it.
"""

from __future__ import annotations

import statistics
import sys
import tempfile
import time
from pathlib import Path

import mujoco

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from bench._harness import summary, table  # noqa: E402
from launcher.sim.loading import load_world_file  # noqa: E402

HERE = Path(__file__).resolve().parent
EXTERNAL = HERE.parent.parent / "shared" / "external" / "gz-sim" / "worlds"
COUNT = 1000


def load_seconds(path: Path) -> float:
    start = time.perf_counter()
    load_world_file(path).spec.compile()
    return time.perf_counter() - start


def ratio_of_loads(sdf: Path, mjcf: Path, rounds: int = 40) -> tuple[list[float], float, float]:
    for _ in range(3):  # warm: imports, caches
        load_seconds(sdf), load_seconds(mjcf)
    sdf_times, mjcf_times = [], []
    for _ in range(rounds):
        sdf_times.append(load_seconds(sdf))
        mjcf_times.append(load_seconds(mjcf))
    ratios = [s / m for s, m in zip(sdf_times, mjcf_times, strict=True)]
    return ratios, statistics.median(sdf_times), statistics.median(mjcf_times)


def many_models(folder: Path) -> tuple[Path, Path]:
    """1,000 boxes in a grid on the ground, as SDF models and as the same MJCF bodies."""
    side = int(COUNT ** 0.5) + 1
    places = [(i % side * 1.5, i // side * 1.5) for i in range(COUNT)]
    link = ("<inertial><mass>1</mass><inertia><ixx>0.0417</ixx><iyy>0.0417</iyy>"
            "<izz>0.0417</izz></inertia></inertial>"
            "<collision name='c'><geometry><box><size>0.5 0.5 0.5</size></box></geometry>"
            "</collision><visual name='v'><geometry><box><size>0.5 0.5 0.5</size></box>"
            "</geometry><material><diffuse>0.6 0.4 0.2 1</diffuse></material></visual>")
    models = "".join(f"<model name='box_{i}'><pose>{x} {y} 0.25 0 0 0</pose>"
                     f"<link name='link'>{link}</link></model>" for i, (x, y) in
                     enumerate(places))
    ground = ("<model name='ground_plane'><static>true</static><link name='link'>"
              "<collision name='c'><geometry><plane><normal>0 0 1</normal><size>100 100</size>"
              "</plane></geometry></collision></link></model>")
    sdf = folder / "boxes.sdf"
    sdf.write_text(f"<sdf version='1.9'><world name='boxes'><physics>"
                   f"<max_step_size>0.001</max_step_size></physics>{ground}{models}"
                   "</world></sdf>")
    bodies = "".join(
        f"<body name='box_{i}/link' pos='{x} {y} 0.25'><freejoint/>"
        "<inertial pos='0 0 0' mass='1' diaginertia='0.0417 0.0417 0.0417'/>"
        "<geom type='box' size='0.25 0.25 0.25' group='3'/>"
        "<geom type='box' size='0.25 0.25 0.25' contype='0' conaffinity='0' group='1' "
        "density='0' rgba='0.6 0.4 0.2 1'/></body>" for i, (x, y) in enumerate(places))
    mjcf = folder / "boxes.xml"
    mjcf.write_text("<mujoco model='boxes'><option timestep='0.001' integrator='implicitfast'/>"
                    "<worldbody><body name='ground_plane/link'><geom type='plane' "
                    f"size='50 50 1' group='3'/></body>{bodies}</worldbody></mujoco>")
    return sdf, mjcf


def steps_per_second(model: mujoco.MjModel, data: mujoco.MjData, seconds: float) -> float:
    steps, start = 0, time.perf_counter()
    while time.perf_counter() - start < seconds:
        mujoco.mj_step(model, data, nstep=50)
        steps += 50
    return steps / (time.perf_counter() - start)


def main() -> None:
    rows = []
    for name in ("shapes", "diff_drive"):
        if not (EXTERNAL / f"{name}.sdf").exists():  # gz-sim's worlds live beside the repo
            print(f"{EXTERNAL / name}.sdf is not here: the load of gz-sim's {name}.sdf is "
                  "left out")
            continue
        ratios, sdf_time, mjcf_time = ratio_of_loads(EXTERNAL / f"{name}.sdf",
                                                     HERE / "worlds" / f"{name}.xml")
        rows.append((f"load {name}.sdf, ms (SDF / MJCF by hand)", "report",
                     f"{sdf_time * 1e3:.2f} / {mjcf_time * 1e3:.2f}"))
        rows.append((f"load {name}.sdf / the same in MJCF", "<= 1.5", summary(ratios)))
    folder = Path(tempfile.mkdtemp(prefix="launcher-bench-sdf-"))
    sdf, mjcf = many_models(folder)
    ratios, sdf_time, mjcf_time = ratio_of_loads(sdf, mjcf, rounds=5)
    rows.append((f"load {COUNT} SDF models, s", "report", f"{sdf_time:.3f}"))
    rows.append((f"load {COUNT} models: SDF / MJCF", "report", summary(ratios)))
    models = {}
    for label, path in (("sdf", sdf), ("mjcf", mjcf)):
        model = load_world_file(path).spec.compile()
        data = mujoco.MjData(model)
        mujoco.mj_step(model, data, nstep=200)  # settle onto the ground
        models[label] = (model, data)
    shares, sdf_rates = [], []
    for _ in range(5):  # interleaved rounds
        sdf_rate = steps_per_second(*models["sdf"], 1.0)
        mjcf_rate = steps_per_second(*models["mjcf"], 1.0)
        sdf_rates.append(sdf_rate)
        shares.append(100 * sdf_rate / mjcf_rate)
    rows.append((f"{COUNT} models: steps/s of the SDF world", "report", summary(sdf_rates)))
    rows.append((f"{COUNT} models: SDF steps/s, % of MJCF", ">= 95", summary(shares)))
    table("SDF worlds (bench/sdf.py)", rows)


if __name__ == "__main__":
    main()
