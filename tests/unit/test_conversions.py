"""The bridge's conversions on real CDR payloads, both ways where both ways exist."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest

from launcher.bus.messages import build
from launcher.bus.types import registry
from launcher.errors import LaunchError
from launcher.nodes import bridge_config, conversions

POSE = {"position": {"x": 1.0, "y": -2.0, "z": 0.5},
        "orientation": {"x": 0.0, "y": 0.0, "z": 0.6, "w": 0.8}}
TWIST = {"linear": {"x": 0.5, "y": 0.0, "z": 0.0}, "angular": {"x": 0.0, "y": 0.0, "z": 0.2}}
HEADER = {"stamp": {"sec": 3, "nanosec": 400}, "frame_id": "bot/odom"}


def encode(type_name, fields):
    return bytes(registry().serialize(build(type_name, fields), type_name))


def decode(type_name, payload):
    return registry().deserialize(payload, type_name)


def convert(ros, sim, fields, way="to_ros"):
    conversion = conversions.find(ros, conversions.sim_type(sim))
    source, target = (conversions.sim_type(sim), ros) if way == "to_ros" else \
        (ros, conversions.sim_type(sim))
    return decode(target, getattr(conversion, way)(encode(source, fields)))


def test_clock_is_the_sims_sim_time():
    clock = convert("rosgraph_msgs/msg/Clock", "gz.msgs.Clock",
                    {"sim": {"sec": 12, "nanosec": 5}, "real": {"sec": 99}, "paused": True,
                     "iterations": 7})
    assert (clock.clock.sec, clock.clock.nanosec) == (12, 5)


@pytest.mark.parametrize("ros, sim, fields", [
    ("geometry_msgs/msg/Twist", "gz.msgs.Twist", TWIST),
    ("std_msgs/msg/Float64", "gz.msgs.Double", {"data": 2.5}),
    ("std_msgs/msg/Bool", "gz.msgs.Boolean", {"data": True}),
    ("std_msgs/msg/Int32", "gz.msgs.Int32", {"data": -7}),
    ("std_msgs/msg/String", "gz.msgs.StringMsg", {"data": "hello"}),
    ("std_msgs/msg/Empty", "gz.msgs.Empty", {}),
])
def test_same_layouts_pass_through_both_ways(ros, sim, fields):
    there = convert(ros, sim, fields, "to_ros")
    back = convert(ros, sim, fields, "to_sim")
    assert encode(ros, fields) == bytes(registry().serialize(there, ros))
    assert encode(conversions.sim_type(sim), fields) == \
        bytes(registry().serialize(back, conversions.sim_type(sim)))


def test_odometry_both_ways_and_twist_stamped():
    odom = convert("nav_msgs/msg/Odometry", "gz.msgs.Odometry",
                   {"header": HEADER, "child_frame_id": "bot/base_link", "pose": POSE,
                    "twist": TWIST})
    assert odom.header.frame_id == "bot/odom" and odom.child_frame_id == "bot/base_link"
    assert odom.pose.pose.position.y == -2.0 and odom.twist.twist.angular.z == 0.2
    back = convert("nav_msgs/msg/Odometry", "gz.msgs.Odometry",
                   {"header": HEADER, "pose": {"pose": POSE}, "twist": {"twist": TWIST}},
                   "to_sim")
    assert back.pose.orientation.w == 0.8 and back.header.stamp.nanosec == 400
    assert back.twist.angular.z == 0.2
    for child in ("", "b", "bo", "bot/base_link_x"):  # every string padding
        fields = {"header": {**HEADER, "frame_id": child * 2}, "child_frame_id": child,
                  "pose": POSE, "twist": TWIST}
        payload = encode("mujoco_sim/msg/Odometry", fields)
        conversion = conversions.find("nav_msgs/msg/Odometry", "mujoco_sim/msg/Odometry")
        assert conversion.to_ros(payload) == conversions._odometry_objects_to_ros(payload)
        assert conversion.to_sim(conversion.to_ros(payload)) == payload
    stamped = convert("geometry_msgs/msg/TwistStamped", "gz.msgs.Twist", TWIST)
    assert stamped.twist.linear.x == 0.5
    plain = convert("geometry_msgs/msg/TwistStamped", "gz.msgs.Twist",
                    {"header": HEADER, "twist": TWIST}, "to_sim")
    assert plain.angular.z == 0.2


def test_pose_v_to_tf_model_to_joint_state_and_poses():
    tf = convert("tf2_msgs/msg/TFMessage", "gz.msgs.Pose_V",
                 {"header": HEADER, "name": ["bot/base_link"], "parent": ["bot/odom"],
                  "pose": [POSE]})
    transform = tf.transforms[0]
    assert (transform.header.frame_id, transform.child_frame_id) == ("bot/odom",
                                                                      "bot/base_link")
    assert transform.transform.translation.x == 1.0 and transform.header.stamp.sec == 3
    joints = convert("sensor_msgs/msg/JointState", "gz.msgs.Model",
                     {"header": HEADER, "name": "bot", "joint_name": ["a", "b"],
                      "position": np.array([0.1, 0.2]), "velocity": np.array([1.0, 2.0]),
                      "effort": np.array([0.0, 0.0])})
    assert list(joints.name) == ["a", "b"] and list(joints.velocity) == [1.0, 2.0]
    pose = convert("geometry_msgs/msg/PoseStamped", "gz.msgs.Pose",
                   {"header": HEADER, "name": "bot", "pose": POSE})
    assert pose.pose.position.z == 0.5 and pose.header.frame_id == "bot/odom"
    plain = convert("geometry_msgs/msg/Pose", "gz.msgs.Pose", POSE, "to_sim")
    assert plain.pose.orientation.z == 0.6


def test_unsupported_pairs_and_unknown_types_say_what_is_supported():
    with pytest.raises(LaunchError) as error:
        conversions.find("geometry_msgs/msg/Twist", "mujoco_sim/msg/Odometry")
    assert "geometry_msgs/msg/Twist pairs with: gz.msgs.Twist" in str(error.value)
    with pytest.raises(LaunchError) as error:
        conversions.find("sensor_msgs/msg/Temperature", "mujoco_sim/msg/Odometry")
    assert "does not convert sensor_msgs/msg/Temperature; it converts:" in str(error.value)
    with pytest.raises(LaunchError) as error:
        conversions.sim_type("gz.msgs.WorldControl|gz.msgs.Double")
    assert "the sim has no service taking" in str(error.value)
    assert conversions.sim_type("gz.msgs.EntityFactory|gz.msgs.Boolean") == \
        "mujoco_sim/srv/Create"


@pytest.mark.parametrize("text, direction, service", [
    ("/clock@rosgraph_msgs/msg/Clock[gz.msgs.Clock", "GZ_TO_ROS", False),
    ("/cmd_vel@geometry_msgs/msg/Twist]gz.msgs.Twist", "ROS_TO_GZ", False),
    ("/chatter@std_msgs/msg/String@gz.msgs.StringMsg", "BIDIRECTIONAL", False),
    ("/world/w/control@ros_gz_interfaces/srv/ControlWorld@gz.msgs.WorldControl",
     "BIDIRECTIONAL", True),
])
def test_the_command_line_form(text, direction, service):
    entry = bridge_config.parse_argument(
        text, bridge_config.Types(conversions.sim_type, conversions.known_ros_type))
    assert entry.direction == direction and entry.service == service


def test_converting_reads_and_writes_plain_objects_without_numpy():
    """The bridge's first joint_states message used to import numpy (~0.1 s) for the
    message classes' arrays; the conversion needs none, and writes the same bytes."""
    code = """
import sys
from types import SimpleNamespace as N
from launcher.bus.types import registry
from launcher.nodes import conversions
types = registry()
model = N(header=N(stamp=N(sec=3, nanosec=5), frame_id='f'), name='bot', joint_name=['a'],
          position=[1.5], velocity=[0.5], effort=[0.0])
payload = types.writer('mujoco_sim/msg/Model')(model)
out = conversions.find('sensor_msgs/msg/JointState', 'mujoco_sim/msg/Model').to_ros(payload)
print('numpy' in sys.modules, out.hex())
"""
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=60)
    imported, payload = done.stdout.split()
    assert imported == "False", done.stderr
    expected = build("sensor_msgs/msg/JointState", {
        "header": {"stamp": {"sec": 3, "nanosec": 5}, "frame_id": "f"}, "name": ["a"],
        "position": [1.5], "velocity": [0.5], "effort": [0.0]})
    assert bytes.fromhex(payload) == bytes(registry().store.serialize_cdr(
        expected, "sensor_msgs/msg/JointState"))


def test_a_scan_of_several_rows_reaches_ros_as_its_middle_row():
    """ros_gz_bridge's: a gz LaserScan of `vertical_count` rows of `count` becomes a ROS
    LaserScan of the middle row (no scan_time); a ROS scan reaches the sim as one row."""
    from launcher.bus.types import registry

    reg = registry()
    cls = reg.message_class
    header = cls("std_msgs/msg/Header")(stamp=cls("builtin_interfaces/msg/Time")(
        sec=1, nanosec=2), frame_id="m::l::lidar")
    rows = [float(i) for i in range(12)]  # 3 rows of 4
    scan = cls("mujoco_sim/msg/LaserScan")(
        header=header, angle_min=-1.0, angle_max=1.0, angle_increment=2 / 3,
        time_increment=0.0, scan_time=0.1, range_min=0.1, range_max=10.0,
        ranges=np.array(rows, dtype=np.float32), intensities=np.zeros(12, dtype=np.float32),
        count=4, vertical_angle_min=-0.2, vertical_angle_max=0.2, vertical_angle_step=0.2,
        vertical_count=3)
    conversion = conversions.find("sensor_msgs/msg/LaserScan", "mujoco_sim/msg/LaserScan")
    ros = reg.reader("sensor_msgs/msg/LaserScan")(conversion.to_ros(
        reg.writer("mujoco_sim/msg/LaserScan")(scan)))
    assert list(ros.ranges) == [4.0, 5.0, 6.0, 7.0] and ros.scan_time == 0.0
    assert ros.header.frame_id == "m::l::lidar"
    back = reg.reader("mujoco_sim/msg/LaserScan")(conversion.to_sim(
        reg.writer("sensor_msgs/msg/LaserScan")(ros)))
    assert (back.count, back.vertical_count, list(back.ranges)) == (4, 0, [4.0, 5.0, 6.0, 7.0])


def test_the_sensors_types_pass_through_the_bridge_as_ros_lays_them_out():
    """The sim's sensor messages are laid out as sensor_msgs' (their bytes go across as they
    are); NavSat becomes a NavSatFix from GPS."""
    from launcher.bus.types import registry

    reg = registry()
    for ros, sim in (("sensor_msgs/msg/Imu", "IMU"),
                     ("sensor_msgs/msg/PointCloud2", "PointCloudPacked"),
                     ("sensor_msgs/msg/MagneticField", "Magnetometer"),
                     ("sensor_msgs/msg/FluidPressure", "FluidPressure"),
                     ("ros_gz_interfaces/msg/Altimeter", "Altimeter"),
                     ("ros_gz_interfaces/msg/Contacts", "Contacts"),
                     ("ros_gz_interfaces/msg/AirSpeed", "AirSpeedSensor"),
                     ("geometry_msgs/msg/WrenchStamped", "Wrench")):
        assert reg.fields(reg.ensure(ros)) == reg.fields(reg.ensure(f"mujoco_sim/msg/{sim}"))
        conversion = conversions.find(ros, f"mujoco_sim/msg/{sim}")
        assert conversion.to_ros(b"\x00\x01\x00\x00abc") == b"\x00\x01\x00\x00abc"
    fix = reg.writer("mujoco_sim/msg/NavSat")(reg.message_class("mujoco_sim/msg/NavSat")(
        header=reg.message_class("std_msgs/msg/Header")(
            stamp=reg.message_class("builtin_interfaces/msg/Time")(sec=1, nanosec=2),
            frame_id="m::l::gps"),
        latitude_deg=45.0, longitude_deg=7.0, altitude=200.0, velocity_east=0.0,
        velocity_north=0.0, velocity_up=0.0))
    converted = conversions.find("sensor_msgs/msg/NavSatFix",
                                 "mujoco_sim/msg/NavSat").to_ros(fix)
    read = reg.reader("sensor_msgs/msg/NavSatFix", lambda name, values: values)(converted)
    assert read[2:5] == [45.0, 7.0, 200.0] and read[1][1] == 1  # status.service: GPS
    back = reg.deserialize(conversions.find("sensor_msgs/msg/NavSatFix", "mujoco_sim/msg/NavSat")
                           .to_sim(converted), "mujoco_sim/msg/NavSat")
    assert (back.latitude_deg, back.longitude_deg, back.altitude, back.header.frame_id) == \
        (45.0, 7.0, 200.0, "m::l::gps")  # and back, as ros_gz_bridge's `@` pairs allow


def test_navsat_becomes_a_gps_fix_with_speed_track_and_climb_and_comes_back():
    """gps_msgs/GPSFix (navsat_gpsfix's mapping): the track in degrees clockwise from north,
    as GPSFix defines it."""
    reg = registry()
    cls = reg.message_class
    fix = reg.writer("mujoco_sim/msg/NavSat")(cls("mujoco_sim/msg/NavSat")(
        header=cls("std_msgs/msg/Header")(stamp=cls("builtin_interfaces/msg/Time")(
            sec=3, nanosec=4), frame_id="m::l::gps"),
        latitude_deg=-35.0, longitude_deg=149.0, altitude=600.0, velocity_east=3.0,
        velocity_north=-3.0, velocity_up=0.5))
    conversion = conversions.find("gps_msgs/msg/GPSFix", "mujoco_sim/msg/NavSat")
    gps = reg.deserialize(conversion.to_ros(fix), "gps_msgs/msg/GPSFix")
    assert (gps.header.stamp.sec, gps.header.frame_id) == (3, "m::l::gps")
    assert (gps.latitude, gps.longitude, gps.altitude) == (-35.0, 149.0, 600.0)
    assert gps.speed == pytest.approx(18 ** 0.5) and gps.climb == 0.5
    assert gps.track == pytest.approx(135.0)  # south-east
    assert gps.status.status == 2 and gps.position_covariance_type == 0
    back = reg.deserialize(conversion.to_sim(reg.writer("gps_msgs/msg/GPSFix")(gps)),
                           "mujoco_sim/msg/NavSat")
    assert (back.velocity_east, back.velocity_north, back.velocity_up) == \
        pytest.approx((3.0, -3.0, 0.5))


def test_a_wrench_loses_its_header_to_geometry_msgs_wrench_and_gains_one_back():
    reg = registry()
    cls = reg.message_class
    vector = cls("geometry_msgs/msg/Vector3")
    stamped = reg.writer("mujoco_sim/msg/Wrench")(cls("mujoco_sim/msg/Wrench")(
        header=cls("std_msgs/msg/Header")(stamp=cls("builtin_interfaces/msg/Time")(
            sec=1, nanosec=2), frame_id="m::j::ft"),
        wrench=cls("geometry_msgs/msg/Wrench")(force=vector(x=1.0, y=2.0, z=3.0),
                                               torque=vector(x=4.0, y=5.0, z=6.0))))
    conversion = conversions.find("geometry_msgs/msg/Wrench", "mujoco_sim/msg/Wrench")
    plain = conversion.to_ros(stamped)
    assert reg.reader("geometry_msgs/msg/Wrench", lambda name, values: values)(plain) == \
        [[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]]
    back = reg.reader("mujoco_sim/msg/Wrench", lambda name, values: values)(
        conversion.to_sim(plain))
    assert back[1] == [[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]]
