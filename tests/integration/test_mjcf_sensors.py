"""An MJCF's own sensors on the ROS graph with no plugin: real sim, real MuJoCo, real Zenoh,
read back with `launcher topic echo` as any ROS tool would."""

from __future__ import annotations

import re

import pytest

from tests.support.nodes import stop

WORLD = """<mujoco model="sensed">
  <custom>
    <text name="ros_cameras" data="front_cam rear_cma"/>
    <numeric name="ros_camera_rate" data="10"/>
  </custom>
  <worldbody>
    <camera name="front_cam" pos="-1 0 0.5" xyaxes="0 -1 0 0 0 1" resolution="320 240"/>
    <camera name="rear_cam" pos="3 0 0.5" xyaxes="0 1 0 0 0 1"/>
    <geom name="floor" type="plane" size="5 5 0.1"/>
    <geom name="wall" type="box" size="0.1 5 5" pos="2.1 0 0"/>
    <body name="probe" pos="0 0 0.1">
      <freejoint/>
      <geom name="pad" type="box" size="0.1 0.1 0.1" mass="1"/>
      <site name="imu" pos="0 0 0"/>
      <site name="front" pos="0.1 0 0" zaxis="1 0 0"/>
      <site name="pad_site" type="box" size="0.11 0.11 0.11"/>
    </body>
  </worldbody>
  <sensor>
    <accelerometer name="acc" site="imu"/>
    <gyro name="gyr" site="imu"/>
    <framequat name="orient" objtype="site" objname="imu"/>
    <rangefinder name="front_range" site="front" cutoff="5"/>
    <touch name="pad_touch" site="pad_site"/>
    <force name="f" site="imu"/>
    <torque name="t" site="imu"/>
  </sensor>
</mujoco>
"""
ROBOT = """<mujoco model="bot"><worldbody><body name="base">
<geom type="box" size=".2 .1 .05" mass="2"/><site name="nose" pos=".2 0 0" zaxis="1 0 0"/>
</body></worldbody><sensor><rangefinder name="nose_range" site="nose"/></sensor></mujoco>"""


@pytest.fixture
def sensed(ws):
    ws.own_bus()
    ws.write("sensed.xml", WORLD)
    sim = ws.start("sim", "-r", "-v", "3", "sensed.xml", output="sim.out")
    try:
        ws.wait_for_output("world 'sensed'", 60, "sim.out")
        yield ws
    finally:
        assert stop(sim) in (0, 130)


def echo(ws, topic: str, type_name: str) -> str:
    done = ws.run("topic", "echo", topic, type_name, "--once", timeout=30)
    assert done.returncode == 0, done.stderr
    return done.stdout


def value(text: str, field: str) -> float:
    return float(re.search(rf"^\s*{field}: (\S+)$", text, re.M).group(1))


def test_a_rangefinder_is_a_range_to_what_it_sees(sensed):
    text = echo(sensed, "/front_range", "sensor_msgs/msg/Range")
    assert value(text, "range") == pytest.approx(1.9, abs=1e-3)  # the wall's face, 1.9 m on
    assert value(text, "max_range") == 5.0 and "frame_id: front" in text, text


def test_accelerometer_gyro_and_framequat_on_a_site_are_one_imu(sensed):
    text = echo(sensed, "/imu/imu", "sensor_msgs/msg/Imu")
    acceleration = text.split("linear_acceleration:")[1]
    assert value(acceleration, "z") == pytest.approx(9.81, abs=0.05)  # resting: gravity's
    assert value(text.split("orientation:")[1], "w") == pytest.approx(1.0, abs=1e-3)
    assert "frame_id: imu" in text, text


def test_a_touch_sensor_is_the_normal_force_it_feels(sensed):
    text = echo(sensed, "/pad_touch", "std_msgs/msg/Float64")
    assert value(text, "data") == pytest.approx(9.81, abs=0.1)  # one kilogram, resting


def test_force_and_torque_on_a_site_are_one_wrench(sensed):
    text = echo(sensed, "/imu/wrench", "geometry_msgs/msg/WrenchStamped")
    assert "force:" in text and "torque:" in text and "frame_id: imu" in text, text


def test_a_spawned_mjcf_robots_sensors_are_under_its_name(sensed):
    sensed.write("bot.xml", ROBOT)
    done = sensed.run("run", "ros_gz_sim", "create", "-file", "bot.xml", "-name", "r1",
                      "-y", "1", "-z", "0.06", timeout=60)
    assert done.returncode == 0, done.stderr
    text = echo(sensed, "/r1/nose_range", "sensor_msgs/msg/Range")
    assert value(text, "range") == pytest.approx(1.8, abs=1e-2)  # the wall, from x = 0.2


def test_a_declared_camera_is_a_ros_camera_at_its_resolution(sensed):
    done = sensed.run("topic", "echo", "/front_cam/color", "sensor_msgs/msg/Image", "--once",
                      "--field", "width", timeout=60)
    assert done.returncode == 0, done.stderr
    assert done.stdout.split()[0] == "320", done.stdout
    info = echo(sensed, "/front_cam/camera_info", "sensor_msgs/msg/CameraInfo")
    assert re.search(r"^height: 240$", info, re.M) and "frame_id: front_cam_frame" in info, info


def test_a_declared_camera_the_model_lacks_is_a_warning_naming_the_nearest(sensed):
    out = sensed.output("sim.out")
    assert "ros_cameras: 'rear_cma' is not a camera of the model (did you mean 'rear_cam'?)" \
        in out, out


def test_a_removed_robots_sensor_topics_go_with_it(sensed):
    sensed.write("bot.xml", ROBOT)
    done = sensed.run("run", "ros_gz_sim", "create", "-file", "bot.xml", "-name", "r1",
                      "-y", "1", "-z", "0.06", timeout=60)
    assert done.returncode == 0, done.stderr
    assert "/r1/nose_range" in sensed.run("topic", "list", timeout=30).stdout.split()
    deleted = sensed.run("service", "call", "/gzserver/delete_entity",
                         "simulation_interfaces/srv/DeleteEntity", "{entity: r1}", timeout=60)
    assert deleted.returncode == 0, deleted.stderr
    assert "/r1/nose_range" not in sensed.run("topic", "list", timeout=30).stdout.split()
