#!/usr/bin/env python3
"""MuJoCo users' benchmarks (issue 42), each against its reference in the same run.

Test robot: mujoco_ros2_control's demo 01 unchanged (its test robot, controller_manager at
100 Hz with its four controllers, its plugins), launched as a user launches it: the sim's
real-time factor from /clock and its CPU (cores), against the same MJCF scene stepped raw in
this process (`mj_step`, the cores real time takes); the difference is what control, the
plugins and serving the graph cost.

Camera: the demo's camera (640 × 480, colour and aligned depth) through mujoco_ros2_control's
CameraPlugin, at the demos' 6 Hz (frames delivered against frames due, and the RTF), and due
at every control cycle (frames delivered against mujoco.Renderer drawing the same camera's
colour and depth in this process, as fast as it can).

Spawning: 50 robots into a world, one recompile each against SpawnEntities' batch of one
(in process, the sim's own World).

Stepping: simulation_interfaces' SimulateSteps of 1,000 steps on a paused sim (a real sim
process, the action through the bus), against `mj_step` × 1,000 on the same world here.

The fifty-robot launch is in bench/demo.py; the depth of every camera in bench/sensors.py.
"""

from __future__ import annotations

import os
import struct
import subprocess
import sys
import tempfile
import time
import uuid
from pathlib import Path

import psutil
from _harness import launcher_cmd, start_router, stop, summary, table

REPO = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPO))
DEMOS = REPO.parent / "shared" / "external" / "mujoco_ros2_control" / "mujoco_ros2_control_demos"
SCENE = DEMOS / "demo_resources" / "scenes" / "scene.xml"
CLOCK = struct.Struct("<4xiI")
WINDOW = float(os.environ.get("BENCH_MUJOCO_SECONDS", "8"))


def raw_cost(path: Path, steps: int = 4000) -> float:
    """Cores that stepping the MJCF at real time takes, raw (`mj_step` in this process)."""
    import mujoco

    model = mujoco.MjModel.from_xml_path(str(path))
    data = mujoco.MjData(model)
    start = time.process_time()
    for _ in range(steps):
        mujoco.mj_step(model, data)
    return (time.process_time() - start) / (steps * model.opt.timestep)


def launch(env: dict, *args: str, output: Path) -> subprocess.Popen:
    return subprocess.Popen([*launcher_cmd(), "launch", *args], env=env, cwd=output.parent,
                            stdout=output.open("w"), stderr=subprocess.STDOUT)


def wait_text(path: Path, text: str, timeout: float = 120.0) -> None:
    deadline = time.monotonic() + timeout
    while text not in path.read_text():
        if time.monotonic() > deadline:
            raise RuntimeError(f"{text!r} not in {path}:\n{path.read_text()[-2000:]}")
        time.sleep(0.1)


def sim_process(launch_pid: int) -> psutil.Process:
    """The launch's ros2_control_node (the sim)."""
    for child in psutil.Process(launch_pid).children(recursive=True):
        try:
            if "mujoco_ros2_control_node" in " ".join(child.cmdline()):
                return child
        except psutil.Error:
            continue
    raise RuntimeError("no ros2_control_node in the launch")


def watch(node, seconds: float, topics: tuple[str, ...] = ()) -> tuple[float, list[int]]:
    """(RTF from /clock, messages per topic) over `seconds` of wall time."""
    clocks: list[tuple[float, float]] = []
    counts = [0] * len(topics)

    def on_clock(payload: bytes) -> None:
        sec, nanosec = CLOCK.unpack_from(payload)
        clocks.append((time.monotonic(), sec + nanosec * 1e-9))

    def counter(index: int):
        def count(_payload: bytes) -> None:
            counts[index] += 1
        return count

    subscriptions = [node.create_subscription("rosgraph_msgs/msg/Clock", "/clock", on_clock,
                                              raw=True, inline=True)]
    subscriptions += [node.create_subscription("sensor_msgs/msg/Image", topic, counter(i),
                                               raw=True, inline=True)
                      for i, topic in enumerate(topics)]
    node.spin(2.0)  # subscribed: the camera starts, the clock flows
    clocks.clear()
    counts[:] = [0] * len(topics)
    node.spin(seconds)
    for subscription in subscriptions:
        subscription.destroy()
    (wall0, sim0), (wall1, sim1) = clocks[0], clocks[-1]
    return (sim1 - sim0) / (wall1 - wall0), counts


def test_robot(env: dict, folder: Path) -> tuple[float, float]:
    """(RTF, sim CPU in cores) of demo 01 with its controllers."""
    from launcher.bus.node import Node

    out = folder / "demo01.out"
    proc = launch(env, "mujoco_ros2_control_demos", "01_basic_robot.launch.py",
                  "headless:=true", output=out)
    node = Node("bench_mujoco", argv=[])
    try:
        wait_text(out, "Configured and activated pose_broadcaster")
        sim = sim_process(proc.pid)
        before = sim.cpu_times()
        rtf, _ = watch(node, WINDOW)
        after = sim.cpu_times()
        return rtf, (after.user + after.system - before.user - before.system) / (WINDOW + 2.0)
    finally:
        node.destroy_node()
        stop(proc)


CAMERA_LAUNCH = """launch:
  - let:
      name: description
      value: "$(command 'xacro {urdf} use_pid:=false headless:=true
        use_mjcf_from_topic:=false use_transmissions:=false')"
  - node:
      pkg: robot_state_publisher
      exec: robot_state_publisher
      param: [{{name: robot_description, value: $(var description)}},
              {{name: use_sim_time, value: true}}]
  - node:
      pkg: mujoco_ros2_control
      exec: ros2_control_node
      output: screen
      param: [{{from: {controllers}}}, {{from: {plugins}}}, {{from: {override}}},
              {{name: use_sim_time, value: true}}]
"""
TOPICS = ("/camera/color/image_raw", "/camera/aligned_depth_to_color/image_raw")


def camera(env: dict, folder: Path, rate: float) -> tuple[float, float]:
    """(frames per second delivered, colour and depth both, RTF) with the camera at `rate`."""
    from launcher.bus.node import Node

    override = folder / f"camera_{rate:g}.yaml"
    override.write_text("/**:\n  ros__parameters:\n    mujoco_plugins:\n      "
                        f"mujoco_camera_plugin:\n        camera_publish_rate: {rate}\n")
    description = folder / f"camera_{rate:g}.launch.yaml"
    description.write_text(CAMERA_LAUNCH.format(
        urdf=DEMOS / "demo_resources" / "robot" / "test_robot.urdf",
        controllers=DEMOS / "config" / "controllers.yaml",
        plugins=DEMOS / "config" / "mujoco_ros2_control_plugins.yaml", override=override))
    out = folder / f"camera_{rate:g}.out"
    proc = launch(env, str(description), output=out)
    node = Node("bench_camera", argv=[])
    try:
        wait_text(out, "mujoco plugin 'mujoco_camera_plugin' (CameraPlugin) loaded")
        rtf, counts = watch(node, WINDOW, TOPICS)
        return min(counts) / WINDOW, rtf
    finally:
        node.destroy_node()
        stop(proc)


def raw_camera_fps(seconds: float = 4.0) -> float:
    """mujoco.Renderer alone drawing the demo camera's colour and depth, as fast as it can."""
    import mujoco

    model = mujoco.MjModel.from_xml_path(str(SCENE))
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    colour, depth = mujoco.Renderer(model, 480, 640), mujoco.Renderer(model, 480, 640)
    depth.enable_depth_rendering()
    frames, start = 0, time.perf_counter()
    while time.perf_counter() - start < seconds:
        for renderer in (colour, depth):
            renderer.update_scene(data, camera="camera")
            renderer.render()
        frames += 1
    colour.close()
    depth.close()
    return frames / (time.perf_counter() - start)


ROBOT = REPO / "tests" / "data" / "diffbot.urdf"


def spawning(count: int = 50) -> tuple[float, float]:
    """(s to spawn `count` robots one recompile each, s as one batch), same world kind."""
    from launcher.sim.entity import Spawn
    from launcher.sim.resources import find_world
    from launcher.sim.world import World
    from tests.support.sim import Recorder

    times = []
    for batched in (False, True):
        world = World.from_path(find_world("empty.sdf"), Recorder())
        template = world.templates.from_file(str(ROBOT))
        requests = [Spawn(template, f"bot{i}", [float(i % 10), float(i // 10), 0.1],
                          [1.0, 0.0, 0.0, 0.0]) for i in range(count)]
        start = time.perf_counter()
        if batched:
            world.spawn_all(requests)
        else:
            for request in requests:
                world.spawn_all([request])
        times.append(time.perf_counter() - start)
        assert len(world.entities) == count + 1
    return times[0], times[1]


def simulate_steps(env: dict, folder: Path, steps: int = 1000) -> tuple[float, float, float]:
    """(s for SimulateSteps of `steps` through the bus, s for StepSimulation of as many, s
    for `mj_step` × `steps` raw on the same world) on the demo scene, paused."""
    import mujoco

    from launcher.bus import actions
    from launcher.bus.node import Node

    sim = subprocess.Popen([*launcher_cmd(), "sim", "-v", "1", str(SCENE)], env=env,
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    node = Node("bench_steps", argv=[])
    kind = "simulation_interfaces/action/SimulateSteps"
    try:
        goal = node.create_client(actions.send_goal_type(kind),
                                  actions.endpoint("/gzserver/simulate_steps", "send_goal"))
        result = node.create_client(actions.get_result_type(kind),
                                    actions.endpoint("/gzserver/simulate_steps", "get_result"))
        step = node.create_client("simulation_interfaces/srv/StepSimulation",
                                  "/gzserver/step_simulation")
        for client in (goal, result, step):
            assert client.wait_for_service(60)
        action_times, service_times = [], []
        for _ in range(5):
            goal_id = node.message("unique_identifier_msgs/msg/UUID",
                                   uuid=list(uuid.uuid4().bytes))
            start = time.perf_counter()
            accepted = goal.call(node.message(f"{actions.send_goal_type(kind)}_Request",
                                              goal_id=goal_id, goal={"steps": steps}))
            assert accepted.accepted
            done = result.call(node.message(f"{actions.get_result_type(kind)}_Request",
                                            goal_id=goal_id), timeout=60)
            action_times.append(time.perf_counter() - start)
            assert done.result.result.result == 1, done.result.result.error_message
            start = time.perf_counter()
            answer = step.call(node.message("simulation_interfaces/srv/StepSimulation_Request",
                                            steps=steps), timeout=60)
            service_times.append(time.perf_counter() - start)
            assert answer.result.result == 1, answer.result.error_message
    finally:
        node.destroy_node()
        sim.terminate()
        sim.wait(10)
    model = mujoco.MjModel.from_xml_path(str(SCENE))
    data = mujoco.MjData(model)
    raw = []
    for _ in range(5):
        start = time.perf_counter()
        for _ in range(steps):
            mujoco.mj_step(model, data)
        raw.append(time.perf_counter() - start)
    return sorted(action_times)[2], sorted(service_times)[2], sorted(raw)[2]


def main() -> None:
    env, router = start_router()
    env["LAUNCHER_PACKAGE_PATH"] = str(DEMOS)
    os.environ.setdefault("MUJOCO_GL", "egl")
    folder = Path(tempfile.mkdtemp(prefix="launcher-bench-mujoco-"))
    try:
        raws, rtfs, cpus = [], [], []
        for _ in range(2):  # interleaved: raw, then the demo
            raws.append(raw_cost(SCENE))
            rtf, cpu = test_robot(env, folder)
            rtfs.append(rtf)
            cpus.append(cpu)
        extra = [c - r * t for c, r, t in zip(cpus, raws, rtfs, strict=True)]
        demo_rate, demo_rtf = camera(env, folder, 6.0)
        raw_fps, delivered, camera_rtfs = [], [], []
        for _ in range(2):
            raw_fps.append(raw_camera_fps())
            fps, rtf = camera(env, folder, 1000.0)
            delivered.append(fps)
            camera_rtfs.append(rtf)
        one_by_one, batch = spawning()
        action, service, raw_steps = simulate_steps(env, folder)
        table("MuJoCo users (mujoco_ros2_control, spawning, SimulateSteps)", [
            ("demo 01 test robot: sim RTF, 4 controllers at 100 Hz", ">= 0.95",
             summary(rtfs)),
            ("demo 01: sim CPU (cores)", "report", summary(cpus)),
            ("same MJCF stepped raw at real time (cores)", "report", summary(raws)),
            ("control, plugins and graph: sim CPU - raw (cores)", "<= 0.15", summary(extra)),
            ("camera at the demos' 6 Hz: frames delivered / due", ">= 0.80",
             f"{demo_rate / 6.0:.3f}"),
            ("sim RTF while the camera streams at 6 Hz", ">= 0.95", f"{demo_rtf:.3f}"),
            ("raw mujoco.Renderer, demo camera colour + depth, fps", "report",
             summary(raw_fps)),
            ("CameraPlugin due every cycle: colour + depth fps delivered", "report",
             summary(delivered)),
            ("delivered / raw fps (same run)", ">= 0.80",
             summary([d / r for d, r in zip(delivered, raw_fps, strict=True)])),
            ("sim RTF while the camera streams flat out", ">= 0.95", summary(camera_rtfs)),
            ("50 robots spawned one recompile each, s", "report", f"{one_by_one:.3f}"),
            ("50 robots spawned as one batch (SpawnEntities), s", "report", f"{batch:.3f}"),
            ("batch / one by one", "report", f"{batch / one_by_one:.3f}"),
            ("SimulateSteps 1000, paused, through the bus, s (median of 5)", "report",
             f"{action:.4f}"),
            ("StepSimulation 1000, s (median of 5)", "report", f"{service:.4f}"),
            ("mj_step x 1000 raw, same world, s (median of 5)", "report", f"{raw_steps:.4f}"),
            ("SimulateSteps / raw", "report", f"{action / raw_steps:.2f}"),
        ])
    finally:
        router.terminate()
        router.wait(10)


if __name__ == "__main__":
    main()
