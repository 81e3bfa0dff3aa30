"""Gazebo's sensors on launcher's sim (launcher/sim/sensors): what they read is checked
against geometry and physics, not only against shapes. The world is stepped without a bus
(a recording transport); the end-to-end tests run them over the real one."""

from __future__ import annotations

import json
import math
import re
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from launcher.errors import LaunchError
from launcher.sim.sensors.atmosphere import pressure_at
from launcher.sim.sensors.geodesy import SphericalCoordinates
from launcher.sim.world import World
from tests.support.sim import Recorder

SYSTEMS = """
<plugin filename="gz-sim-sensors-system" name="gz::sim::systems::Sensors"/>
<plugin filename="gz-sim-imu-system" name="gz::sim::systems::Imu"/>
<plugin filename="gz-sim-magnetometer-system" name="gz::sim::systems::Magnetometer"/>
<plugin filename="libignition-gazebo6-altimeter-system.so" name="x"/>
<plugin filename="ignition-gazebo-air-pressure-system" name="y"/>
<plugin filename="gz-sim-navsat-system" name="gz::sim::systems::NavSat"/>"""


class Listening(Recorder):
    """The recording transport, with a subscriber count per topic (1 unless set)."""

    def __init__(self) -> None:
        super().__init__()
        self.subscribers: dict[str, int] = {}

    def publisher(self, type_name, topic, qos=10, ros=False):
        box = self.published.setdefault(topic, [])
        return SimpleNamespace(publish=box.append, destroy=lambda: None,
                               get_subscription_count=lambda: self.subscribers.get(topic, 1))


def world_with(tmp_path: Path, sensors: str, extra: str = "", systems: str = SYSTEMS,
               pose: str = "0 0 0.5 0 0 0", static: bool = True, seed: int = 0,
               world_extra: str = "", model_extra: str = "") -> World:
    """A world with ground, a 1 m box (`box`, its link `link` carrying `sensors`, the model
    `model_extra`) and `extra` models."""
    text = f"""<?xml version="1.0"?>
<sdf version="1.9"><world name="w">{systems}{world_extra}
<model name="ground"><static>true</static><link name="link"><collision name="c"><geometry>
<plane><normal>0 0 1</normal><size>50 50</size></plane></geometry></collision></link></model>
<model name="box"><static>{str(static).lower()}</static><pose>{pose}</pose>
<link name="link"><inertial><mass>1</mass><inertia><ixx>0.1</ixx><iyy>0.1</iyy><izz>0.1</izz>
</inertia></inertial><collision name="c"><geometry><box><size>1 1 1</size></box></geometry>
</collision>{sensors}</link>{model_extra}</model>{extra}
</world></sdf>"""
    path = tmp_path / "world.sdf"
    path.write_text(text)
    return World.from_path(path, Listening(), environ={}, seed=seed)


def run(world: World, seconds: float) -> None:
    """Step as the server does (batches up to the next sensor's update), `seconds` of sim
    time and no more."""
    steps = round(seconds / world.model.opt.timestep)
    while steps > 0:
        batch = world.physics.steps_until_update(min(steps, 100))
        world.physics.step(batch)
        steps -= batch


def sensor(name: str, kind: str, body: str = "", rate: float = 100, pose: str = "",
           topic: str = "") -> str:
    return (f'<sensor name="{name}" type="{kind}"><update_rate>{rate}</update_rate>'
            f'{f"<pose>{pose}</pose>" if pose else ""}'
            f'{f"<topic>{topic}</topic>" if topic else ""}{body}</sensor>')


# --- the IMU, magnetometer, altimeter, air pressure and navsat ---------------------------
def test_an_imu_at_rest_reads_gravity_up_and_its_first_orientation(tmp_path):
    world = world_with(tmp_path, sensor("imu", "imu"), static=False, pose="0 0 0.5 0 0 0.7")
    run(world, 0.5)
    topic = "/world/w/model/box/link/link/sensor/imu/imu"  # gz-sim's scoped topic
    readings = world.transport.published[topic]
    assert 45 <= len(readings) <= 55  # 100 Hz of sim time
    last = readings[-1]
    assert (last.linear_acceleration.x, last.linear_acceleration.y) == \
        pytest.approx((0, 0), abs=0.05)
    assert last.linear_acceleration.z == pytest.approx(9.8, abs=0.05)
    assert last.header.frame_id == "box::link::imu"
    assert (last.orientation.x, last.orientation.y, last.orientation.z, last.orientation.w) \
        == pytest.approx((0, 0, 0, 1), abs=1e-3)  # the yaw it started with is its zero


@pytest.mark.parametrize("frame, expected", [
    ("<localization>ENU</localization>", (0, 0, math.sin(0.35), math.cos(0.35))),
    # NED: x north, z down; a sensor yawed 0.7 from east faces 90° - 40° = 50° from north
    ("<localization>NED</localization>", None),
    ("<localization>CUSTOM</localization><custom_rpy parent_frame='world'>0 0 0.7"
     "</custom_rpy>", (0, 0, 0, 1)),
    ("<localization>WSU</localization>", (0, 0, 0, 1)),  # unknown: its first orientation
])
def test_an_imus_orientation_is_against_the_frame_its_reference_names(tmp_path, frame,
                                                                       expected):
    body = f"<imu><orientation_reference_frame>{frame}</orientation_reference_frame></imu>"
    world = world_with(tmp_path, sensor("imu", "imu", body), pose="0 0 0.5 0 0 0.7")
    run(world, 0.05)
    q = world.transport.published["/world/w/model/box/link/link/sensor/imu/imu"][-1].orientation
    if expected is None:  # NED: the reading's rotation takes north-east-down to the body
        from launcher.sim.transform import from_rpy, rotate
        body_x = rotate((q.w, q.x, q.y, q.z), (1.0, 0.0, 0.0))
        east_yaw = from_rpy(0, 0, 0, 0, 0, 0.7)
        north, east = rotate(east_yaw.quat, (1.0, 0.0, 0.0))[1], \
            rotate(east_yaw.quat, (1.0, 0.0, 0.0))[0]
        assert body_x == pytest.approx((north, east, 0.0), abs=1e-6)
        return
    assert (q.x, q.y, q.z, q.w) == pytest.approx(expected, abs=1e-6)
    if "WSU" in frame:
        said = world.transport.messages("warning")
        assert any("<localization> 'WSU' is not one Gazebo knows" in m for m in said), said


def test_an_imu_without_orientation_says_so_as_ros_does(tmp_path):
    body = "<imu><enable_orientation>false</enable_orientation></imu>"
    world = world_with(tmp_path, sensor("imu", "imu", body))
    run(world, 0.05)
    reading = world.transport.published["/world/w/model/box/link/link/sensor/imu/imu"][-1]
    q = reading.orientation
    assert (q.x, q.y, q.z, q.w) == (0, 0, 0, 0)
    assert list(reading.orientation_covariance)[0] == -1  # REP 145: no orientation
    assert reading.linear_acceleration.z == pytest.approx(9.8, abs=0.05)


def test_a_magnetometer_reads_the_worlds_field_in_its_own_frame(tmp_path):
    world = world_with(tmp_path, sensor("mag", "magnetometer", pose="0 0 0 0 0 1.5707963"),
                       world_extra="<magnetic_field>1e-5 2e-5 -4e-5</magnetic_field>")
    run(world, 0.05)
    field = world.transport.published[
        "/world/w/model/box/link/link/sensor/mag/magnetometer"][-1].magnetic_field
    # turned 90° about z: the world's y is its x, the world's -x its y
    assert (field.x, field.y, field.z) == pytest.approx((2e-5, -1e-5, -4e-5), abs=1e-9)


def test_an_altimeter_reads_height_and_speed_against_where_it_started(tmp_path):
    world = world_with(tmp_path, sensor("alt", "altimeter", topic="altimeter"), static=False,
                       pose="0 0 3 0 0 0")
    run(world, 0.3)  # falling
    reading = world.transport.published["/altimeter"][-1]
    t = world.data.time
    assert reading.vertical_reference == pytest.approx(3.0, abs=1e-6)
    assert reading.vertical_position == pytest.approx(-0.5 * 9.8 * t * t, abs=0.03)
    assert reading.vertical_velocity == pytest.approx(-9.8 * t, abs=0.05)


def test_air_pressure_is_the_standard_atmospheres_at_the_height(tmp_path):
    world = world_with(tmp_path, sensor("p", "air_pressure",
                                        "<air_pressure><reference_altitude>1000"
                                        "</reference_altitude></air_pressure>"))
    run(world, 0.05)
    reading = world.transport.published["/world/w/model/box/link/link/sensor/p/air_pressure"]
    assert pressure_at(0) == pytest.approx(101325)
    assert pressure_at(1000) == pytest.approx(89875, rel=1e-3)  # the standard atmosphere's
    assert reading[-1].fluid_pressure == pytest.approx(pressure_at(1000.5), rel=1e-9)


def test_navsat_reads_the_worlds_spherical_coordinates(tmp_path):
    world = world_with(tmp_path, sensor("gps", "navsat"), pose="1000 0 0 0 0 0", world_extra="""
    <spherical_coordinates><surface_model>EARTH_WGS84</surface_model>
    <latitude_deg>45</latitude_deg><longitude_deg>7</longitude_deg><elevation>200</elevation>
    <heading_deg>0</heading_deg></spherical_coordinates>""")
    run(world, 0.05)
    fix = world.transport.published["/world/w/model/box/link/link/sensor/gps/navsat"][-1]
    assert fix.latitude_deg == pytest.approx(45, abs=1e-6)
    # 1000 m east at 45°: a degree of longitude is 78.85 km there (WGS84)
    assert fix.longitude_deg == pytest.approx(7 + 1000 / 78846.8, abs=1e-5)
    assert fix.altitude == pytest.approx(200.0, abs=0.2)  # the Earth curves 0.08 m in 1 km


def test_geodesy_round_trips_and_the_heading_turns_the_world():
    here = SphericalCoordinates(45.0, 7.0, 200.0, 90.0)
    assert here.geodetic(0, 0, 0) == pytest.approx((45.0, 7.0, 200.0), abs=1e-6)
    assert here.enu(1, 0, 0) == pytest.approx((0, -1, 0), abs=1e-12)  # x points south


# --- the lidar -----------------------------------------------------------------------------
LIDAR = """<lidar><scan><horizontal><samples>{h}</samples><resolution>1</resolution>
<min_angle>{lo}</min_angle><max_angle>{hi}</max_angle></horizontal>
<vertical><samples>{v}</samples><min_angle>-0.1</min_angle><max_angle>0.1</max_angle></vertical>
</scan><range><min>0.08</min><max>10</max><resolution>0.01</resolution></range></lidar>"""


def wall(x: float, name: str = "wall") -> str:
    return f"""<model name="{name}"><static>true</static><pose>{x} 0 1 0 0 0</pose>
<link name="link"><collision name="c"><geometry><box><size>0.2 20 4</size></box></geometry>
</collision><visual name="v"><geometry><box><size>0.2 20 4</size></box></geometry></visual>
</link></model>"""


def test_a_lidar_ray_reads_a_face_at_its_distance_and_nothing_beyond_its_range(tmp_path):
    """The box carrying the sensor is left out; a wall whose near face is 2.5 m ahead reads
    2.5 m within the range resolution; rays to the side reach nothing within 10 m."""
    body = LIDAR.format(h=181, lo=-math.pi / 2, hi=math.pi / 2, v=3)
    world = world_with(tmp_path, sensor("lidar", "gpu_lidar", body, rate=10), wall(2.6))
    run(world, 0.15)
    scans = world.transport.published["/world/w/model/box/link/link/sensor/lidar/scan"]
    assert len(scans) == 2  # 10 Hz
    scan = scans[-1]
    ranges = list(scan.ranges)
    assert len(ranges) == 3 * 181 and scan.header.frame_id == "box::link::lidar"
    middle = ranges[181 + 90]  # the level row, straight ahead
    assert middle == pytest.approx(2.5, abs=0.01)
    assert ranges[181] == math.inf  # 90° to the right: nothing within 10 m
    assert (scan.angle_min, scan.angle_max) == pytest.approx((-math.pi / 2, math.pi / 2))
    points = world.transport.published[
        "/world/w/model/box/link/link/sensor/lidar/scan/points"][-1]
    assert (points.width, points.height, points.point_step) == (181, 3, 16)


def test_a_lidar_does_no_work_while_nobody_listens_unless_always_on(tmp_path):
    body = LIDAR.format(h=10, lo=-0.5, hi=0.5, v=1)
    world = world_with(tmp_path, sensor("lazy", "gpu_lidar", body, rate=10) +
                       sensor("eager", "gpu_lidar", "<always_on>true</always_on>" + body,
                              rate=10))
    for topic in list(world.transport.published):
        world.transport.subscribers[topic] = 0
    run(world, 0.35)
    published = world.transport.published
    assert published["/world/w/model/box/link/link/sensor/lazy/scan"] == []
    assert len(published["/world/w/model/box/link/link/sensor/eager/scan"]) == 4
    world.transport.subscribers["/world/w/model/box/link/link/sensor/lazy/scan"] = 1
    run(world, 0.3)
    assert len(published["/world/w/model/box/link/link/sensor/lazy/scan"]) >= 2


# --- systems, noise, bad input -------------------------------------------------------------
def test_a_sensor_whose_system_the_world_lacks_publishes_nothing_and_says_why(tmp_path):
    world = world_with(tmp_path, sensor("imu", "imu"), systems="")
    run(world, 0.1)
    # not even advertised, as in Gazebo
    assert "/world/w/model/box/link/link/sensor/imu/imu" not in world.transport.published
    said = [m for m in world.transport.messages("warning") if "sensor 'imu'" in m]
    assert len(said) == 1 and "does not load gz-sim-imu-system" in said[0]


def test_a_cpu_lidar_runs_under_gz_sims_cpu_lidar_system_as_under_the_sensors_one(tmp_path):
    """gz-sim 9 runs `type="lidar"` in gz-sim-cpu-lidar-system; a gpu_lidar still needs the
    sensors system."""
    lidars = (sensor("cpu", "lidar", LIDAR.format(h=8, v=1, lo=-1, hi=1), rate=10) +
              sensor("gpu", "gpu_lidar", LIDAR.format(h=8, v=1, lo=-1, hi=1), rate=10))
    world = world_with(tmp_path, lidars, systems='<plugin filename="gz-sim-cpu-lidar-system" '
                       'name="gz::sim::systems::CpuLidar"/>')
    run(world, 0.25)
    published = world.transport.published
    assert len(published["/world/w/model/box/link/link/sensor/cpu/scan"]) >= 2
    assert "/world/w/model/box/link/link/sensor/gpu/scan" not in published
    said = [m for m in world.transport.messages("warning") if "gz-sim-cpu-lidar" in m]
    assert not said  # the system is one launcher provides: no "runs without it"


def test_enable_metrics_publishes_the_sensors_rates_as_gz_sensors_does(tmp_path):
    world = world_with(tmp_path, sensor("imu", "imu", "<enable_metrics>true</enable_metrics>",
                                        rate=50, topic="imu"))
    run(world, 0.2)
    metrics = world.transport.published["/imu/performance_metrics"]
    assert 9 <= len(metrics) <= 11  # one per update
    assert metrics[0].sim_update_rate == 0.0  # no update before the first
    assert metrics[-1].name == "box::link::imu"
    assert metrics[-1].sim_update_rate == pytest.approx(50, rel=1e-6)
    assert metrics[-1].nominal_update_rate == 50 and metrics[-1].real_update_rate > 0
    plain = world_with(tmp_path, sensor("imu", "imu", rate=50, topic="imu"))
    run(plain, 0.1)
    assert "/imu/performance_metrics" not in plain.transport.published


NOISY = """<imu><linear_acceleration><x><noise type="gaussian"><mean>0</mean><stddev>0.5</stddev>
</noise></x></linear_acceleration></imu>"""


def test_noise_is_seeded_per_sensor(tmp_path):
    def readings(seed: int) -> list[float]:
        world = world_with(tmp_path, sensor("imu", "imu", NOISY), seed=seed)
        run(world, 0.1)
        return [r.linear_acceleration.x for r in
                world.transport.published["/world/w/model/box/link/link/sensor/imu/imu"]]

    first, again, other = readings(1), readings(1), readings(2)
    assert first == again and first != other
    assert 0.2 < (sum(x * x for x in first) / len(first)) ** 0.5 < 0.8  # stddev 0.5


@pytest.mark.parametrize("body, kind, expected", [
    ("", "imuu", None),
    ("<update_rate>-5</update_rate>", "imu", "<update_rate> must be a number of Hz ≥ 0"),
    ("<update_rate>fast</update_rate>", "imu", "got 'fast'"),
    (LIDAR.format(h=0, lo=0, hi=1, v=1), "gpu_lidar", "<horizontal><samples> must be a whole"),
    (LIDAR.format(h=10, lo=1, hi=0, v=1), "gpu_lidar", "<min_angle> 1 is above <max_angle> 0"),
    (LIDAR.format(h=100000, lo=0, hi=1, v=100), "gpu_lidar", "10000000 rays a scan is more"),
    ('<noise type="pink"/>', "altimeter", "<noise type='pink'>: expected one of none, gaussian"),
], ids=["unknown-type", "negative-rate", "rate-not-a-number", "no-samples", "min-above-max",
        "too-many-rays", "noise-type"])
def test_bad_sensor_input_is_located_and_leaves_the_sensor_out(tmp_path, body, kind, expected):
    """A sensor whose settings are wrong is one error at its file:line, and left out; the
    world runs on (as a plugin that fails is)."""
    text = f'<sensor name="s" type="{kind}">{body}</sensor>'
    if kind == "altimeter":
        text = f'<sensor name="s" type="altimeter"><altimeter><vertical_position>{body}' \
               '</vertical_position></altimeter></sensor>'
    world = world_with(tmp_path, text)
    run(world, 0.05)
    said = "\n".join(world.transport.messages("warning" if expected is None else "error"))
    if expected is None:
        assert "world.sdf:14: sensor 's': unknown type 'imuu' (did you mean 'imu'" in said
        return
    assert re.search(r"world\.sdf:1[45]:\d+: sensor 's' .*" + re.escape(expected), said), said
    assert said.endswith("is left out") and "Traceback" not in said
    assert not any(world.transport.published.get(t) for t in world.transport.published
                   if "/sensor/s/" in t)


def test_two_sensors_of_one_name_in_a_link_are_an_error(tmp_path):
    with pytest.raises(LaunchError, match="two sensors named 'imu' in link 'link'"):
        world_with(tmp_path, sensor("imu", "imu") + sensor("imu", "magnetometer"))


# --- cameras: their settings, checked where the sim reads them ----------------------------
def camera(body: str = "", kind: str = "camera", topic: str = "") -> str:
    return sensor("cam", kind, f"<camera>{body}</camera>", rate=10, topic=topic)


@pytest.mark.parametrize("body, expected", [
    ("<image><width>0</width><height>48</height></image>",
     "<image><width> must be a whole number of pixels from 1 to 8192, got '0'"),
    ("<image><width>100000</width><height>48</height></image>",
     "<image><width> must be a whole number of pixels from 1 to 8192, got '100000'"),
    ("<image><width>8000</width><height>8000</height></image>",
     "8000 x 8000 pixels is more than the 16777216 a frame may hold"),
    ("<image><format>R8G8B9</format></image>",
     "unknown image format 'R8G8B9' (did you mean 'R8G8B8'"),
    ("<horizontal_fov>4</horizontal_fov>", "<horizontal_fov> must be a number from 0.001 to"),
    ("<clip><near>2</near><far>1</far></clip>", "<clip><far> must be a number from 2 to inf"),
], ids=["no-pixels", "too-wide", "too-many-pixels", "format", "fov", "clip"])
def test_a_cameras_bad_settings_are_located_and_leave_it_out(tmp_path, monkeypatch, body,
                                                              expected):
    monkeypatch.setenv("LAUNCHER_RENDERER", "none")  # (the renderer process is not the point)
    world = world_with(tmp_path, camera(body))
    run(world, 0.05)
    said = "\n".join(world.transport.messages("error"))
    assert "world.sdf:14" in said and expected in said and "is left out" in said, said


@pytest.mark.parametrize("kind, topic, expected", [
    ("camera", "", {"image": "/world/w/model/box/link/link/sensor/cam/image",
                    "camera_info": "/world/w/model/box/link/link/sensor/cam/camera_info"}),
    ("camera", "front", {"image": "/front", "camera_info": "/camera_info"}),
    ("depth_camera", "depth", {"depth_image": "/depth", "points": "/depth/points",
                               "camera_info": "/camera_info"}),
    ("rgbd_camera", "rgbd", {"image": "/rgbd/image", "depth_image": "/rgbd/depth_image",
                             "points": "/rgbd/points", "camera_info": "/rgbd/camera_info"}),
    ("segmentation_camera", "seg", {"labels_map": "/seg/labels_map",
                                    "colored_map": "/seg/colored_map",
                                    "camera_info": "/seg/camera_info"}),
], ids=["default", "camera", "depth", "rgbd", "segmentation"])
def test_cameras_publish_on_gz_sensors_topics(tmp_path, monkeypatch, kind, topic, expected):
    monkeypatch.setenv("LAUNCHER_RENDERER", "none")
    world = world_with(tmp_path, camera(kind=kind, topic=topic))
    plugin = world.entities["box"].plugins[0]
    assert plugin.topics() == expected
    settings = plugin.settings()
    assert (settings["width"], settings["height"]) == (320, 240)  # SDFormat's defaults
    assert settings["encoding"] == ("32FC1" if kind == "depth_camera" else "rgb8")
    fx = 320 / (2 * math.tan(1.047 / 2))
    assert settings["k"] == pytest.approx([fx, 0, 160, 0, fx, 120, 0, 0, 1])
    assert world.model.cam_fovy[world.model.camera("box/link/sensor/cam").id] == \
        pytest.approx(math.degrees(2 * math.atan(120 / fx)))


def test_a_cameras_info_topic_is_its_camera_info_topic(tmp_path, monkeypatch):
    monkeypatch.setenv("LAUNCHER_RENDERER", "none")
    world = world_with(tmp_path, camera("<camera_info_topic>front/info</camera_info_topic>",
                                        topic="front"))
    assert world.entities["box"].plugins[0].topics() == {"image": "/front",
                                                         "camera_info": "/front/info"}


def test_a_renderer_that_lacks_the_model_is_sent_it_again(tmp_path, monkeypatch):
    """The model is published once per change; a renderer that missed it (its route to the
    sim formed late) says the version it holds (-1: none) with the cameras it wants, and gets
    the same model again: not while the model may still be on its way, and at most once
    every 2 s. A renderer that says only the cameras, as a plain list, is still heard."""
    monkeypatch.setenv("LAUNCHER_RENDERER", "none")
    world = world_with(tmp_path, camera())
    now = [100.0]
    world.rendering.clock = lambda: now[0]
    run(world, 0.05)
    sent = world.transport.published["/world/w/render/model"]
    assert [model.version for model in sent] == [1]
    (name,) = world.rendering.cameras
    say = world.transport.callbacks["/world/w/render/wanted"]

    def holds(version, after):
        now[0] += after
        say(SimpleNamespace(data=json.dumps({"cameras": [name], "version": version})))
        return len(sent) - 1  # the times the model was sent again

    assert holds(-1, after=0.5) == 0  # (the first sending may not have arrived yet)
    assert holds(1, after=2.0) == 0 and world.rendering.wants(name)
    assert holds(-1, after=0.0) == 1 and sent[1] is sent[0]  # the same model, version 1
    assert holds(-1, after=1.5) == 1  # within 2 s of the last sending
    assert holds(0, after=0.6) == 2
    assert "the renderer holds model version -1, not 1: sending it again" in \
        world.transport.messages("debug")
    say(SimpleNamespace(data=json.dumps([])))
    assert not world.rendering.wants(name)
    now[0] += 10
    say(SimpleNamespace(data=json.dumps([name])))
    assert world.rendering.wants(name) and len(sent) == 3


def test_a_cameras_noise_is_gz_sensors_image_noise_seeded_per_camera(tmp_path, monkeypatch):
    """`<camera><noise>`: a gaussian draw added to each channel in colour units of 0..1
    (clamped), and to each depth in metres; the same seed gives the same noise."""
    import numpy as np

    from launcher.sim.sensors.noise import generator
    from launcher.sim.sensors.pictures import add_noise

    monkeypatch.setenv("LAUNCHER_RENDERER", "none")
    noisy = camera("<noise><type>gaussian</type><mean>0.01</mean><stddev>0.02</stddev></noise>")
    settings = world_with(tmp_path, noisy, seed=3).entities["box"].plugins[0].settings()
    assert settings["noise"] == [0.01, 0.02] and settings["seed"] == 3

    def drawn(picture, unit):
        rng = generator(settings["seed"], settings["name"])
        return add_noise(picture, rng, *settings["noise"], unit)

    grey = np.full((240, 320, 3), 128, np.uint8)
    first, again = drawn(grey, 255.0), drawn(grey, 255.0)
    assert first.dtype == np.uint8 and np.array_equal(first, again)
    offsets = first.astype(float) - 128
    assert offsets.mean() == pytest.approx(0.01 * 255, abs=0.2)
    assert offsets.std() == pytest.approx(0.02 * 255, rel=0.05)
    assert drawn(np.full((4, 4, 3), 255, np.uint8), 255.0).max() == 255  # clamped
    depth = drawn(np.full((240, 320), 2.0, np.float32), 1.0)
    assert depth.mean() == pytest.approx(2.01, abs=1e-3) and depth.std() == \
        pytest.approx(0.02, rel=0.05)
    plain = world_with(tmp_path, camera()).entities["box"].plugins[0].settings()
    assert plain["noise"] == [0.0, 0.0]


LABELLED = """<model name="car{n}"><static>true</static><pose>{x} 0 0.5 0 0 0</pose>
<link name="l"><visual name="body"><geometry><box><size>1 1 1</size></box></geometry></visual>
<visual name="wheel"><geometry><sphere><radius>0.2</radius></sphere></geometry>{own}</visual>
</link>{label}</model>"""
LABEL = '<plugin filename="gz-sim-label-system" name="gz::sim::systems::Label">' \
        '<label>{}</label></plugin>'


def test_the_label_system_labels_visuals_for_segmentation_as_gz_rendering_does(tmp_path,
                                                                              monkeypatch):
    """gz-sim-label-system in a model labels its visuals, in a visual that visual alone (it
    wins); unlabelled visuals are background. Panoptic maps count instances per label by
    top-level model, from 1."""
    import numpy as np

    from launcher.sim.plugins.label import labels_of
    from launcher.sim.sensors.pictures import segment, segmentation_tables

    monkeypatch.setenv("LAUNCHER_RENDERER", "none")
    cars = "".join(LABELLED.format(n=n, x=3 + 2 * n, label=LABEL.format(40), own="")
                   for n in range(2))
    odd = LABELLED.format(n=2, x=9, label="", own=LABEL.format(7))
    world = world_with(tmp_path, camera("<segmentation_type>instance</segmentation_type>",
                                        kind="segmentation"), extra=cars + odd)
    labels = labels_of(world)
    assert labels == {"car0/l/visual/body": 40, "car0/l/visual/wheel": 40,
                      "car1/l/visual/body": 40, "car1/l/visual/wheel": 40,
                      "car2/l/visual/wheel": 7}
    settings = world.entities["box"].plugins[0].settings()
    assert settings["segmentation"] == "panoptic"
    model = world.model
    tables = segmentation_tables(model, labels)
    geom = {name: model.geom(name).id for name in
            ("car0/l/visual/body", "car1/l/visual/wheel", "car2/l/visual/body",
             "car2/l/visual/wheel")}
    picture = np.full((1, 5, 3), -1, dtype=np.int32)  # the last pixel: nothing there
    picture[0, :4, 0] = list(geom.values())
    picture[0, :4, 1] = 5  # mjOBJ_GEOM
    labels_map, colours = segment(picture, *tables, panoptic=True)
    assert labels_map[0].tolist() == [[1, 0, 40], [2, 0, 40], [0, 0, 0], [1, 0, 7], [0, 0, 0]]
    assert colours[0, 2].tolist() == [0, 0, 0] and colours[0, 0].tolist() != [0, 0, 0]
    assert colours[0, 0].tolist() != colours[0, 1].tolist()  # each instance its colour
    semantic, flat = segment(picture, *tables, panoptic=False)
    assert semantic[0].tolist() == [[40] * 3, [40] * 3, [0] * 3, [7] * 3, [0] * 3]
    assert flat[0, 0].tolist() == flat[0, 1].tolist()  # one colour a label


def test_a_bad_label_or_segmentation_type_is_located(tmp_path, monkeypatch):
    monkeypatch.setenv("LAUNCHER_RENDERER", "none")
    world = world_with(tmp_path, camera("<segmentation_type>semantik</segmentation_type>",
                                        kind="segmentation"),
                       extra=LABELLED.format(n=0, x=3, label=LABEL.format(300), own=""))
    said = "\n".join(world.transport.messages("error"))
    assert "unknown <segmentation_type> 'semantik' (did you mean 'semantic'" in said, said
    assert re.search(r"world\.sdf:\d+: plugin gz::sim::systems::Label: .*300", said), said


def test_a_cameras_distortion_is_the_brown_model_camera_info_gives(tmp_path, monkeypatch):
    """`<distortion>`: camera_info's D is (k1, k2, p1, p2, k3), as gz-sensors gives it; the
    picture is distorted by that model about the principal point, so a direction's pixel
    moves where the model says (and image_proc's rectification puts it back); a barrel lens
    sees past the camera's field of view, so MuJoCo draws a wider picture for it."""
    import numpy as np

    from launcher.sim.sensors.pictures import distort, lens

    monkeypatch.setenv("LAUNCHER_RENDERER", "none")
    body = "<distortion><k1>-0.25</k1><k2>0.12</k2><k3>0</k3><p1>-0.00028</p1>" \
           "<p2>-0.00005</p2><center>0.5 0.5</center></distortion>"
    settings = world_with(tmp_path, camera(body)).entities["box"].plugins[0].settings()
    assert settings["distortion"] == [-0.25, 0.12, -0.00028, -0.00005, 0.0]
    width, height, k = settings["width"], settings["height"], settings["k"]
    found = lens(width, height, k, settings["distortion"])
    fx, cx, cy = k[0], k[2], k[5]
    assert found.width > width and found.height > height  # barrel: it sees more
    assert found.fovy == pytest.approx(math.degrees(2 * math.atan(found.height / (2 * fx))))

    def drawn_pixel(x: float, y: float) -> int:  # a direction's pixel in the wide picture
        return int(y * fx + found.height / 2) * found.width + int(x * fx + found.width / 2)

    # the direction (0.4, 0.3) shows where the model sends it
    x, y = 0.4, 0.3
    k1, k2, p1, p2, k3 = settings["distortion"]
    r2 = x * x + y * y
    radial = 1 + k1 * r2 + k2 * r2 * r2 + k3 * r2 ** 3
    ud = (x * radial + 2 * p1 * x * y + p2 * (r2 + 2 * x * x)) * fx + cx
    vd = (y * radial + p1 * (r2 + 2 * y * y) + 2 * p2 * x * y) * fx + cy
    source = found.index[int(vd) * width + int(ud)]
    assert abs(source % found.width - drawn_pixel(x, y) % found.width) <= 1.5
    assert abs(source // found.width - drawn_pixel(x, y) // found.width) <= 1.5
    assert found.index[int(cy) * width + int(cx)] == drawn_pixel(0.0, 0.0)  # the centre stays
    picture = np.arange(found.width * found.height, dtype=np.float32).reshape(found.height,
                                                                            found.width)
    seen = distort(picture, found, (height, width), np.inf)
    assert seen.shape == (height, width) and seen[int(vd), int(ud)] == source
    assert not np.isinf(seen).any()  # every pixel shows something: the corners see far
    plain = world_with(tmp_path, camera()).entities["box"].plugins[0].settings()
    assert plain["distortion"] == [0.0] * 5


def test_a_camera_looks_along_the_sensors_x_axis(tmp_path, monkeypatch):
    """Gazebo's cameras look along +x with +z up; MuJoCo's along -z with +y up."""
    monkeypatch.setenv("LAUNCHER_RENDERER", "none")
    world = world_with(tmp_path, sensor("cam", "camera", pose="0 0 0 0 0 1.5707963"))
    run(world, 0.001)
    xmat = world.data.cam_xmat[world.model.camera("box/link/sensor/cam").id].reshape(3, 3)
    assert -xmat[:, 2] == pytest.approx([0, 1, 0], abs=1e-6)  # looking along world +y
    assert xmat[:, 1] == pytest.approx([0, 0, 1], abs=1e-6)  # up is up


# --- sensors declared in a URDF, as most ROS robots declare theirs ------------------------
URDF_SENSORS = """<?xml version="1.0"?>
<robot name="bot">
  <link name="base_link">
    <inertial><mass value="2"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/>
    </inertial>
    <collision><geometry><box size="0.4 0.4 0.2"/></geometry></collision>
  </link>
  <link name="imu_link"/>
  <joint name="imu_joint" type="fixed"><parent link="base_link"/><child link="imu_link"/>
    <origin xyz="0 0 0.2"/></joint>
  <link name="laser_link"><inertial><mass value="0.5"/>
    <inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="laser_joint" type="fixed"><parent link="base_link"/><child link="laser_link"/>
    <origin xyz="0 0 0.3"/></joint>
  <gazebo reference="laser_joint"><preserveFixedJoint>true</preserveFixedJoint></gazebo>
  <gazebo reference="imu_link">
    <sensor name="imu" type="imu"><always_on>true</always_on><update_rate>50</update_rate>
    </sensor>
  </gazebo>
  <gazebo reference="laser_link">
    <sensor name="laser" type="gpu_lidar"><update_rate>10</update_rate><topic>scan</topic>
      <lidar><scan><horizontal><samples>4</samples><min_angle>0</min_angle>
      <max_angle>1.5707963</max_angle></horizontal></scan>
      <range><min>0.1</min><max>10</max></range></lidar>
      <plugin name="laser" filename="libgazebo_ros_ray_sensor.so"><ros><namespace>/bot
      </namespace><remapping>~/out:=scan</remapping></ros>
      <output_type>sensor_msgs/LaserScan</output_type></plugin>
    </sensor>
  </gazebo>
  <gazebo reference="base_link">
    <sensor name="bumper" type="contact"><contact><collision>base_link_collision</collision>
    </contact></sensor>
  </gazebo>
  <gazebo reference="laser_joint">
    <sensor name="ft" type="force_torque"><always_on>true</always_on></sensor>
  </gazebo>
  <gazebo reference="imu_lnk">
    <sensor name="lost" type="imu"/>
  </gazebo>
</robot>
"""


def test_a_urdfs_gazebo_sensors_run_on_its_links_named_as_gazebo_names_them(tmp_path):
    """`<gazebo reference="link"><sensor>`: the sensor sits at its link's pose; Gazebo lumps a
    fixed link into its parent, so the IMU on imu_link is named under base_link (its topic
    and frame id as `gz topic -l` shows them) unless the joint is preserved."""
    world = world_with(tmp_path, "", systems=MORE_SYSTEMS, extra="""<model name="wall"><static>true</static>
        <pose>3 0 1 0 0 0</pose><link name="link"><collision name="c"><geometry><box>
        <size>0.2 10 2</size></box></geometry></collision></link></model>""")
    (tmp_path / "bot.urdf").write_text(URDF_SENSORS)
    world.spawn_file(str(tmp_path / "bot.urdf"), "bot", (0, 0, 1.1, 0, 0, 0))
    run(world, 0.5)
    published = world.transport.published
    imu = published["/world/w/model/bot/link/base_link/sensor/imu/imu"]
    assert 20 <= len(imu) <= 30 and imu[-1].header.frame_id == "bot::base_link::imu"
    scan = published["/scan"][-1]
    assert scan.header.frame_id == "bot::laser_link::laser"  # its joint is preserved
    # the first ray looks along x from the laser's height, at the wall's face (2.9 m)
    assert scan.ranges[0] == pytest.approx(2.9, abs=0.02)
    ros = published["/bot/scan"][-1]  # its gazebo_ros plugin's, in the link's frame
    assert ros.header.frame_id == "laser_link" and ros.ranges[0] == scan.ranges[0]
    warned = "\n".join(world.transport.messages("warning"))
    assert re.search(r"bot\.urdf:38:5: sensor 'lost': <gazebo reference=\"imu_lnk\"> names no "
                     r"link or joint of the robot \(did you mean 'imu_link'.*\?\); it is left out",
                     warned)
    site = world.data.site("bot/imu_link/sensor/imu")
    body = world.data.body("bot/base_link")
    assert site.xpos[2] - body.xpos[2] == pytest.approx(0.2, abs=1e-6)
    run(world, 0.6)  # landed: its collision is named as Gazebo's URDF import names it
    touch = published["/world/w/model/bot/link/base_link/sensor/bumper/contact"][-1]
    assert touch.contacts[0].collision1.name == "bot::base_link::base_link_collision"
    # the laser's joint carries the laser's weight
    held = published["/world/w/model/bot/joint/laser_joint/sensor/ft/forcetorque"][-1]
    assert held.wrench.force.z == pytest.approx(0.5 * 9.8, rel=0.05)
    assert held.header.frame_id == "bot::laser_joint::ft"


# --- force-torque, contact and air speed ----------------------------------------------------
MORE_SYSTEMS = SYSTEMS + """
<plugin filename="gz-sim-forcetorque-system" name="gz::sim::systems::ForceTorque"/>
<plugin filename="ignition-gazebo-contact-system" name="c"/>
<plugin filename="libgz-sim8-air-speed-system.so" name="a"/>"""

PENDULUM = """<model name="pendulum"><pose>5 0 0 0 0 0</pose>
<link name="base"/>
<link name="bob"><pose>0 0 1 0 0 0</pose><inertial><mass>2</mass><inertia><ixx>0.01</ixx>
<iyy>0.01</iyy><izz>0.01</izz></inertia></inertial></link>
<joint name="fix" type="fixed"><parent>world</parent><child>base</child></joint>
<joint name="hinge" type="revolute"><parent>base</parent><child>bob</child>
<pose>0 0 0.5 0 0 0</pose><axis><xyz>1 0 0</xyz></axis>
<sensor name="ft" type="force_torque"><update_rate>50</update_rate>{settings}</sensor>
</joint></model>"""


@pytest.mark.parametrize("settings, force, torque", [
    ("", (0, 0, 19.6), (0, 0, 0)),  # the child's frame, the parent holding it up
    ("<force_torque><measure_direction>parent_to_child</measure_direction></force_torque>",
     (0, 0, -19.6), (0, 0, 0)),
], ids=["default", "parent-to-child"])
def test_a_joints_force_torque_sensor_reads_what_the_joint_carries(tmp_path, settings, force,
                                                                 torque):
    """A 2 kg bob hanging still below its hinge (the joint's frame 0.5 m above its centre):
    the joint holds up its weight, and no torque acts about the axis."""
    world = world_with(tmp_path, "", systems=MORE_SYSTEMS,
                       extra=PENDULUM.format(settings=settings))
    run(world, 0.2)
    topic = "/world/w/model/pendulum/joint/hinge/sensor/ft/forcetorque"  # gz-sim's scoped one
    readings = world.transport.published[topic]
    assert 8 <= len(readings) <= 12
    wrench = readings[-1].wrench
    assert (wrench.force.x, wrench.force.y, wrench.force.z) == pytest.approx(force, abs=0.05)
    assert (wrench.torque.x, wrench.torque.y, wrench.torque.z) == pytest.approx(torque,
                                                                                abs=0.05)
    assert readings[-1].header.frame_id == "pendulum::hinge::ft"


def test_a_bad_force_torque_frame_is_located_with_did_you_mean(tmp_path):
    world = world_with(tmp_path, "", systems=MORE_SYSTEMS, extra=PENDULUM.format(
        settings="<force_torque><frame>chidl</frame></force_torque>"))
    run(world, 0.05)
    said = "\n".join(world.transport.messages("error"))
    assert re.search(r"world\.sdf:\d+:\d+: sensor 'ft' \(force_torque\): <frame> 'chidl' is "
                     r"not one of child, parent, sensor \(did you mean 'child'\?\)", said), said


def test_contact_reports_the_colliding_pair_only_while_they_touch(tmp_path):
    """A box dropped onto the ground: nothing while it falls, then the pair (its collision and
    the ground's), points at the ground's height, normals along z, and its weight shared
    among the points."""
    contact = sensor("bumper", "contact", "<contact><collision>c</collision></contact>",
                     rate=0)
    world = world_with(tmp_path, contact, systems=MORE_SYSTEMS, static=False,
                       pose="0 0 0.8 0 0 0")
    run(world, 0.1)
    topic = "/world/w/model/box/link/link/sensor/bumper/contact"
    assert not world.transport.published.get(topic)  # falling: no message at all
    run(world, 1.0)
    last = world.transport.published[topic][-1]
    (pair,) = last.contacts
    assert (pair.collision1.name, pair.collision2.name) == ("box::link::c", "ground::link::c")
    assert pair.collision1.type == 5 and len(pair.positions) >= 1
    assert all(p.z == pytest.approx(0, abs=0.01) for p in pair.positions)
    assert all(abs(n.z) == pytest.approx(1, abs=1e-3) for n in pair.normals)
    lifted = sum(w.body_1_wrench.force.z for w in pair.wrenches)
    assert lifted == pytest.approx(9.8, rel=0.05)  # the ground holds the 1 kg box up


def test_a_contact_sensor_naming_no_collision_says_which_there_are(tmp_path):
    contact = sensor("bumper", "contact", "<contact><collision>cc</collision></contact>")
    world = world_with(tmp_path, contact, systems=MORE_SYSTEMS, static=False)
    run(world, 0.5)
    said = "\n".join(world.transport.messages("warning"))
    assert re.search(r"world\.sdf:\d+: sensor 'bumper' \(contact\): link 'link' has no "
                     r"collision 'cc' \(did you mean 'c'\?\) \(its collisions: c\)", said)
    assert not world.transport.published.get("/world/w/model/box/link/link/sensor/bumper/contact")


def test_air_speed_reads_the_dynamic_pressure_of_flying_forward(tmp_path):
    """A box at 10 m/s along its x axis, 100 m up: ½ρv² with the standard atmosphere's density
    there, and its temperature."""
    world = world_with(tmp_path, sensor("pitot", "air_speed"), systems=MORE_SYSTEMS,
                       static=False, pose="0 0 100 0 0 0",
                       world_extra="<gravity>0 0 0</gravity>")
    world.data.qvel[0] = 10.0
    run(world, 0.05)
    reading = world.transport.published["/world/w/model/box/link/link/sensor/pitot/air_speed"][-1]
    temperature = 288.15 - 0.0065 * 100
    density = 1.225 / (288.15 / temperature) ** 4.256
    assert reading.temperature == pytest.approx(temperature, abs=1e-3)
    assert reading.diff_pressure == pytest.approx(0.5 * density * 100, rel=1e-3)


def test_two_sensors_of_different_types_on_one_topic_leave_the_second_out(tmp_path):
    both = sensor("baro", "air_pressure", topic="air") + sensor("pitot", "air_speed", topic="air")
    world = world_with(tmp_path, both, systems=MORE_SYSTEMS)
    run(world, 0.05)
    said = "\n".join(world.transport.messages("warning"))
    assert re.search(r"world\.sdf:\d+: sensor 'pitot' \(air_speed\) is left out: sensor 'baro' "
                     r"\(air_pressure\) \(.*world\.sdf:\d+\) publishes gz\.msgs\.FluidPressure "
                     r"on /air, and this one would publish gz\.msgs\.AirSpeedSensor there; give "
                     r"one of them a <topic> of its own", said), said
    assert world.transport.published["/air"]
    assert all(hasattr(m, "fluid_pressure") for m in world.transport.published["/air"])


# --- gazebo_ros's sensor plugins: straight onto the ROS graph, as in Gazebo classic -----------
def ray_plugin(name: str, output: str, ros: str = "<namespace>/ray</namespace>",
               extra: str = "") -> str:
    return (f'<plugin name="{name}" filename="libgazebo_ros_ray_sensor.so"><ros>{ros}</ros>'
            f'<output_type>{output}</output_type>{extra}</plugin>')


RAYS = """<ray><scan><horizontal><samples>5</samples><min_angle>-0.2</min_angle>
<max_angle>0.2</max_angle></horizontal><vertical><samples>3</samples><min_angle>-0.1</min_angle>
<max_angle>0.1</max_angle></vertical></scan><range><min>0.05</min><max>20</max></range></ray>"""
WALL = """<model name="wall"><static>true</static><pose>3 0 0.5 0 0 0</pose><link name="link">
<collision name="c"><geometry><box><size>0.2 10 10</size></box></geometry></collision></link>
</model>"""


def test_gazebo_ros_ray_sensor_publishes_each_output_type_in_its_namespace(tmp_path):
    """LaserScan (the middle row of several), PointCloud2 (the rays that hit, dense),
    PointCloud and Range (the nearest ray), on `~/out` after `<remapping>`, in the link's
    frame; the world has no gz-sim system and the sensor runs anyway, as in Gazebo classic."""
    plugins = (ray_plugin("scan", "sensor_msgs/LaserScan",
                          "<namespace>/ray</namespace><remapping>~/out:=scan</remapping>")
               + ray_plugin("pc2", "sensor_msgs/PointCloud2")
               + ray_plugin("pc", "sensor_msgs/PointCloud")
               + ray_plugin("near", "sensor_msgs/Range", extra="<radiation_type>ultrasound"
                            "</radiation_type>"))
    world = world_with(tmp_path, sensor("laser", "ray", RAYS + plugins, rate=10), systems="",
                       extra=WALL)
    run(world, 0.25)
    published = world.transport.published
    scan = published["/ray/scan"][-1]  # remapped
    assert scan.header.frame_id == "link" and len(scan.ranges) == 5
    assert scan.ranges[2] == pytest.approx(2.9, abs=0.01)  # the middle ray of the middle row
    cloud = published["/ray/pc2/out"][-1]  # `~/out` is the plugin's node's
    assert (cloud.height, cloud.width, cloud.point_step, cloud.is_dense) == (1, 15, 16, True)
    xyz = np.frombuffer(cloud.data, dtype=np.float32).reshape(-1, 4)[:, :3]
    assert np.allclose(xyz[:, 0], 2.9, atol=0.01)  # every ray on the wall's face
    assert len(published["/ray/pc/out"][-1].points) == 15
    near = published["/ray/near/out"][-1]
    assert near.range == pytest.approx(2.9, abs=0.01) and near.radiation_type == 0
    assert near.field_of_view == pytest.approx(0.4) and near.max_range == 20


def test_gazebo_ros_imu_gps_and_bumper_publish_their_ros_messages(tmp_path):
    imu = sensor("imu", "imu", '<plugin name="imu" filename="libgazebo_ros_imu_sensor.so">'
                 "<ros><namespace>/bot</namespace><remapping>~/out:=imu</remapping></ros>"
                 "<frame_name>imu_frame</frame_name></plugin>")
    gps = sensor("gps", "gps", '<plugin name="gps" filename="libgazebo_ros_gps_sensor.so">'
                 "<ros><namespace>/bot</namespace></ros></plugin>")
    bumper = sensor("bumper", "contact", "<contact><collision>c</collision></contact>"
                    '<plugin name="bumper" filename="libgazebo_ros_bumper.so"><ros>'
                    "<namespace>/bot</namespace></ros><frame_name>link</frame_name></plugin>",
                    rate=50)
    world = world_with(tmp_path, imu + gps + bumper, systems="", static=False,
                       pose="0 0 0.8 0 0 0")
    run(world, 0.1)
    published = world.transport.published
    assert published["/bot/imu"][-1].header.frame_id == "imu_frame"
    assert published["/bot/imu"][-1].linear_acceleration.z == pytest.approx(0, abs=0.1)  # falls
    fix = published["/bot/gps/out"][-1]
    assert fix.header.frame_id == "link" and fix.status.service == 1
    assert (fix.latitude, fix.longitude) == pytest.approx((0, 0), abs=1e-4)
    assert published["/bot/gps/vel"][-1].vector.z < 0  # falling: up is negative
    states = published["/bot/bumper_states"]
    assert states and states[-1].states == []  # classic's bumper reports while nothing touches
    run(world, 1.0)
    touching = published["/bot/bumper_states"][-1]
    assert touching.header.frame_id == "link"
    (pair,) = touching.states
    assert (pair.collision1_name, pair.collision2_name) == ("box::link::c", "ground::link::c")
    assert pair.total_wrench.force.z == pytest.approx(9.8, rel=0.05)


def test_a_gazebo_ros_camera_names_its_ros_streams(tmp_path, monkeypatch):
    monkeypatch.setenv("LAUNCHER_RENDERER", "none")
    body = ("<camera><image><width>8</width><height>6</height></image></camera>"
            '<plugin name="cam" filename="libgazebo_ros_camera.so"><ros><namespace>demo'
            "</namespace></ros></plugin>")
    world = world_with(tmp_path, sensor("cam1", "depth_camera", body, rate=10))
    camera = next(p for e in world.entities.values() for p in e.plugins
                  if getattr(p, "config", None) is not None and p.config.name == "cam1")
    ros = {o["stream"]: (o["topic"], o["type"], o["frame_id"])
           for o in camera.settings()["ros"]}
    assert ros == {
        "image": ("/demo/cam1/image_raw", "sensor_msgs/msg/Image", "link"),
        "camera_info": ("/demo/cam1/camera_info", "sensor_msgs/msg/CameraInfo", "link"),
        "depth_image": ("/demo/cam1/depth/image_raw", "sensor_msgs/msg/Image", "link"),
        "depth_camera_info": ("/demo/cam1/depth/camera_info", "sensor_msgs/msg/CameraInfo",
                              "link"),
        "points": ("/demo/cam1/points", "sensor_msgs/msg/PointCloud2", "link")}


@pytest.mark.parametrize("plugin, expected", [
    ('<plugin name="x" filename="libgazebo_ros_ray_sensr.so"/>',
     r"plugin 'libgazebo_ros_ray_sensr\.so' is not a sensor plugin launcher runs \(did you "
     r"mean 'libgazebo_ros_ray_sensor\.so'.*\?\)"),
    ('<plugin name="x" filename="libgazebo_ros_camera.so"/>',
     r"plugin 'libgazebo_ros_camera\.so' serves camera or depth_camera or rgbd_camera "
     r"sensors, not this one"),
    (ray_plugin("x", "sensor_msgs/LaserScn"),
     r"<output_type> 'sensor_msgs/LaserScn' is not one of .*\(did you mean "
     r"'sensor_msgs/LaserScan'.*\?\)"),
], ids=["unknown-filename", "wrong-sensor", "bad-output-type"])
def test_a_sensor_plugin_launcher_cannot_run_is_a_located_warning(tmp_path, plugin,
                                                                  expected):
    world = world_with(tmp_path, sensor("laser", "ray", RAYS + plugin, rate=10), extra=WALL)
    run(world, 0.2)
    said = "\n".join(world.transport.messages("warning"))
    assert re.search(r"world\.sdf:\d+: sensor 'laser' \(ray\): " + expected, said), said
    assert not [t for t in world.transport.published if t.startswith("/x")]


def test_gazebo_ros_p3d_and_ft_sensor_report_ground_truth_on_ros_topics(tmp_path):
    truth = ('<plugin name="truth" filename="libgazebo_ros_p3d.so"><ros><namespace>/box'
             "</namespace><remapping>odom:=truth</remapping></ros><body_name>link</body_name>"
             "<update_rate>50</update_rate><xyz_offset>1 0 0</xyz_offset></plugin>")
    ft = ('<plugin name="ft" filename="libgazebo_ros_ft_sensor.so"><ros><namespace>/pendulum'
          "</namespace></ros><joint_name>hinge</joint_name></plugin>")
    pendulum = PENDULUM.format(settings="").replace("</joint></model>", f"</joint>{ft}</model>")
    world = world_with(tmp_path, "", extra=pendulum, static=False, pose="0 0 3 0 0 0",
                       systems=MORE_SYSTEMS, model_extra=truth)
    run(world, 0.5)
    odometry = world.transport.published["/box/truth"]
    assert 20 <= len(odometry) <= 30
    last = odometry[-1]
    assert (last.header.frame_id, last.child_frame_id) == ("world", "link")
    falling = last.header.stamp  # seconds, from rest
    assert last.pose.pose.position.x == pytest.approx(1.0)  # the offset
    assert last.pose.pose.position.z == pytest.approx(3 - 4.9 * falling ** 2, abs=0.01)
    assert last.twist.twist.linear.z == pytest.approx(-9.8 * falling, abs=0.01)
    wrench = world.transport.published["/pendulum/wrench"][-1]
    assert wrench.header.frame_id == "bob"
    assert wrench.wrench.force.z == pytest.approx(19.6, abs=0.05)


@pytest.mark.parametrize("plugin, expected", [
    ('<plugin name="t" filename="libgazebo_ros_p3d.so"/>', "<body_name> is missing"),
    ('<plugin name="t" filename="libgazebo_ros_p3d.so"><body_name>lnk</body_name></plugin>',
     "<body_name> 'lnk' is not a link of 'box' (did you mean 'link'?)"),
    ('<plugin name="t" filename="libgazebo_ros_ft_sensor.so"><joint_name>j</joint_name>'
     "</plugin>", "<joint_name> 'j' is not a moving joint of 'box'"),
], ids=["no-body", "unknown-link", "unknown-joint"])
def test_a_ground_truth_plugins_bad_settings_are_located(tmp_path, plugin, expected):
    world = world_with(tmp_path, "", model_extra=plugin, static=False)
    run(world, 0.05)
    said = "\n".join(world.transport.messages("error") + world.transport.messages("warning"))
    assert re.search(r"world\.sdf:\d+: plugin t: " + re.escape(expected), said), said
