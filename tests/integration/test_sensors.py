"""Gazebo's sensor worlds and ros_gz_sim_demos' sensor launch files, unchanged, on launcher's
sim: real processes (the sim, the bridge, the CLI) on a real router. What Gazebo publishes is
read with `gz topic -e`, what the bridge makes of it with a ROS subscriber."""

from __future__ import annotations

import math
import re
import signal
import time

import pytest

from tests.support.environment import shared
from tests.support.gazebo import demos_workspace

WORLDS = ("external", "gz-sim", "worlds")  # in ../shared


@pytest.fixture
def sensor_ws(ws):
    """gz-sim's worlds on the resource path, and a local Fuel cache holding a stand-in for
    the models they include from Fuel (there is no network here)."""
    ws.own_bus().env["GZ_SIM_RESOURCE_PATH"] = str(shared(*WORLDS))
    cache = ws.root / "fuel"
    for model in ("construction cone", "playground"):
        folder = cache / "fuel.gazebosim.org" / "openrobotics" / "models" / model / "1"
        folder.mkdir(parents=True)
        (folder / "model.config").write_text(
            '<model><name>m</name><sdf version="1.6">model.sdf</sdf></model>')
        (folder / "model.sdf").write_text(f"""<sdf version="1.6"><model name="{model}">
<static>true</static><link name="l"><pose>0 3 1 0 0 0</pose><collision name="c"><geometry>
<box><size>6 0.2 2</size></box></geometry></collision></link></model></sdf>""")
    ws.env["GZ_FUEL_CACHE_PATH"] = str(cache)
    return ws


def stop(proc) -> int:
    proc.send_signal(signal.SIGINT)
    return proc.wait(30)


def test_ros_gz_sim_demos_imu_launch_runs_unchanged_and_the_imu_reads_gravity(sensor_ws):
    demos_workspace(sensor_ws)
    proc = sensor_ws.start("launch", "ros_gz_sim_demos", "imu.launch.py", "rqt:=false",
                           "rviz:=false", output="demo.out")
    try:
        sensor_ws.wait_for_output("bridging 1 of 1 entries", 60, "demo.out")
        # the box falls from 3 m (its IMU reads ~0 in free fall), then rests on the ground
        readings = []
        deadline = time.monotonic() + 40
        while time.monotonic() < deadline:
            done = sensor_ws.run("topic", "echo", "/imu", "sensor_msgs/msg/Imu", "--once",
                                 "--field", "linear_acceleration.z", "--timeout", "30",
                                 timeout=60)
            assert done.returncode == 0, done.stderr
            readings.append(float(done.stdout.split()[0]))
            if readings[-1] == pytest.approx(9.8, abs=0.05):
                break
        assert readings[-1] == pytest.approx(9.8, abs=0.05), readings
        # Gazebo's own view: gz.msgs.IMU in Protocol Buffers' text format
        gz = sensor_ws.run("gz", "topic", "-e", "-t", "/imu", "-n", "1", timeout=60)
        assert gz.returncode == 0, gz.stderr
        assert 'entity_name: "sensors_box::link::imu"' in gz.stdout, gz.stdout
        found = re.search(r"linear_acceleration \{[^}]*z: ([\d.e-]+)", gz.stdout)
        assert found and float(found.group(1)) == pytest.approx(9.8, abs=0.05), gz.stdout
        info = sensor_ws.run("gz", "topic", "-i", "-t", "/imu").stdout
        assert "gz.msgs.IMU" in info, info
        # its rate, as a subscriber gets it (100 Hz of sim time; the machine may be slower)
        rate = re.search(r"Rate: ([\d.]+) Hz \((\d+) messages in 1.5 s\)", info)
        assert rate and 0 < float(rate.group(1)) <= 130, info
        said = sensor_ws.output("demo.out")
        assert "[ERROR]" not in said and "Traceback" not in said, said
    finally:
        assert stop(proc) == 130


def test_ros_gz_sim_demos_gpu_lidar_bridge_gives_laser_scans_and_point_clouds(sensor_ws):
    demos_workspace(sensor_ws)
    proc = sensor_ws.start("launch", "ros_gz_sim_demos", "gpu_lidar_bridge.launch.py",
                           "rviz:=false", output="demo.out")
    try:
        sensor_ws.wait_for_output("bridging 2 of 2 entries", 60, "demo.out")
        scan = sensor_ws.run("topic", "echo", "/lidar", "sensor_msgs/msg/LaserScan", "--once",
                             "--no-arr", "--timeout", "30", timeout=60)
        assert scan.returncode == 0, scan.stderr
        assert "frame_id: model_with_lidar::link::gpu_lidar" in scan.stdout
        # of 16 rows, the middle one: ros_gz_bridge's (a ROS LaserScan is one row)
        assert "length: 640" in scan.stdout and "scan_time: 0.0" in scan.stdout, scan.stdout
        # Gazebo's own: every ray, `count` of a row, and the rows' count and angles
        gz = sensor_ws.run("gz", "topic", "-e", "-t", "/lidar", "-n", "1", timeout=60)
        assert gz.returncode == 0, gz.stderr
        fields = dict(re.findall(r"^(count|vertical_count|vertical_angle_\w+): (\S+)$",
                                 gz.stdout, re.M))
        assert fields["count"] == "640" and fields["vertical_count"] == "16", gz.stdout
        assert float(fields["vertical_angle_min"]) == pytest.approx(-0.261799, abs=1e-5)
        assert float(fields["vertical_angle_max"]) == pytest.approx(0.261799, abs=1e-5)
        assert float(fields["vertical_angle_step"]) == pytest.approx(0.523598 / 15, abs=1e-5)
        assert gz.stdout.count("ranges: ") == 10240
        cloud = sensor_ws.run("topic", "echo", "/lidar/points", "sensor_msgs/msg/PointCloud2",
                              "--once", "--no-arr", "--timeout", "30", timeout=60)
        assert cloud.returncode == 0, cloud.stderr
        assert "width: 640" in cloud.stdout and "height: 16" in cloud.stdout, cloud.stdout
        assert "point_step: 16" in cloud.stdout
    finally:
        assert stop(proc) == 130


def test_gz_sims_sensors_world_publishes_its_sensors_and_says_what_it_lacks(sensor_ws):
    proc = sensor_ws.start("gz", "sim", "-s", "-r", "-v", "3", "sensors.sdf",
                           output="sim.out")
    try:
        sensor_ws.wait_for_output("running", 60, "sim.out")
        listed = sensor_ws.run("gz", "topic", "-l").stdout.split()
        for topic in ("/imu", "/magnetometer", "/altimeter", "/air_pressure"):
            assert topic in listed, listed
        pressure = sensor_ws.run("gz", "topic", "-e", "-t", "/air_pressure", "-n", "1",
                                 timeout=60)
        found = re.search(r"pressure: ([\d.]+)", pressure.stdout)
        assert found and 99000 < float(found.group(1)) < 100500, pressure.stdout  # 123 m up
        wrench = sensor_ws.run("gz", "topic", "-e", "-t", "/world/sensors/model/"
                               "force_torque_demo/joint/joint_01/sensor/force_torque/"
                               "forcetorque", "-n", "1", timeout=60).stdout
        # the 10 kg link stands on its joint: the joint holds it up
        found = re.search(r"force \{[^}]*z: ([\d.]+)", wrench)
        assert found and float(found.group(1)) == pytest.approx(98, rel=0.02), wrench
        assert 'value: "force_torque_demo::joint_01::force_torque"' in wrench, wrench
        # <enable_metrics> on the magnetometer: gz-sensors' performance metrics
        metrics = sensor_ws.run("gz", "topic", "-e", "-t", "/magnetometer/performance_metrics",
                                "-n", "3", timeout=60).stdout
        assert 'name: "sensors_box::link::magnetometer"' in metrics, metrics
        assert "nominal_update_rate: 100" in metrics, metrics
        rates = [float(r) for r in re.findall(r"sim_update_rate: ([\d.e+-]+)", metrics)]
        assert rates[-1] == pytest.approx(100, rel=1e-3), metrics  # in sim time, exactly
        said = sensor_ws.output("sim.out")
        assert ("sensors.sdf:156: sensor 'air_speed' (air_speed) publishes nothing: the world "
                "does not load gz-sim-air-speed-system") in said, said
    finally:
        assert stop(proc) == 0


NAVSAT_WORLD = """<?xml version="1.0"?>
<sdf version="1.9"><world name="geo">
<plugin filename="gz-sim-navsat-system" name="gz::sim::systems::NavSat"/>
<spherical_coordinates><surface_model>EARTH_WGS84</surface_model>
<latitude_deg>-22.9</latitude_deg><longitude_deg>-43.2</longitude_deg><elevation>10</elevation>
<heading_deg>0</heading_deg></spherical_coordinates>
<model name="rover"><pose>0 0 1 0 0 0</pose><link name="link"><inertial><mass>1</mass>
</inertial><sensor name="gps" type="navsat"><always_on>1</always_on><update_rate>10</update_rate>
<topic>navsat</topic></sensor></link></model>
</world></sdf>
"""


def test_the_bridge_gives_navsat_as_a_gps_fix_as_navsat_gpsfix_maps_it(sensor_ws):
    """ros_gz_sim_demos' navsat_gpsfix mapping: gz.msgs.NavSat → gps_msgs/GPSFix; the rover
    falls from 1 m, so it climbs downwards."""
    (sensor_ws.root / "geo.sdf").write_text(NAVSAT_WORLD)
    sim = sensor_ws.start("gz", "sim", "-s", "-r", str(sensor_ws.root / "geo.sdf"),
                          output="sim.out")
    bridge = sensor_ws.start("run", "ros_gz_bridge", "parameter_bridge",
                             "/navsat@gps_msgs/msg/GPSFix@gz.msgs.NavSat", output="bridge.out")
    try:
        sensor_ws.wait_for_output("bridging 1 of 1 entries", 60, "bridge.out")
        fix = sensor_ws.run("topic", "echo", "/navsat", "gps_msgs/msg/GPSFix", "--once",
                            "--timeout", "30", timeout=60)
        assert fix.returncode == 0, fix.stderr
        values = dict(re.findall(r"^(\w+): (\S+)$", fix.stdout, re.M))
        assert float(values["latitude"]) == pytest.approx(-22.9, abs=1e-6), fix.stdout
        assert float(values["longitude"]) == pytest.approx(-43.2, abs=1e-6), fix.stdout
        assert 9.0 < float(values["altitude"]) < 11.01, fix.stdout  # 10 m up, then 1 m
        assert "frame_id: rover::link::gps" in fix.stdout, fix.stdout
        assert re.search(r"^  status: 2$", fix.stdout, re.M), fix.stdout  # STATUS_GBAS_FIX
    finally:
        assert stop(bridge) in (0, 130)
        assert stop(sim) == 0


CAMERA_WORLD = """<?xml version="1.0"?>
<sdf version="1.9"><world name="cam">
<plugin filename="gz-sim-sensors-system" name="gz::sim::systems::Sensors"/>
<light type="directional" name="sun"><pose>0 0 10 0 0 0</pose><diffuse>1 1 1 1</diffuse>
<direction>0 0 -1</direction></light>
<model name="red"><static>true</static><pose>3 0 0.5 0 0 0</pose><link name="l">
<collision name="c"><geometry><box><size>1 1 1</size></box></geometry></collision>
<visual name="v"><geometry><box><size>1 1 1</size></box></geometry>
<material><ambient>1 0 0 1</ambient><diffuse>1 0 0 1</diffuse></material></visual></link>
<plugin filename="gz-sim-label-system" name="gz::sim::systems::Label"><label>40</label></plugin>
</model>
<model name="cam"><static>true</static><pose>0 0 0.5 0 0 0</pose><link name="link">
<sensor name="camera" type="camera"><topic>camera</topic><update_rate>20</update_rate>
<enable_metrics>true</enable_metrics><camera><horizontal_fov>1.047</horizontal_fov><image><width>64</width><height>48</height>
</image><clip><near>0.1</near><far>100</far></clip></camera></sensor>
<sensor name="depth" type="depth_camera"><topic>depth_camera</topic><update_rate>20</update_rate>
<camera><horizontal_fov>1.047</horizontal_fov><image><width>64</width><height>48</height>
<format>R_FLOAT32</format></image><clip><near>0.1</near><far>10</far></clip></camera></sensor>
<sensor name="seg" type="segmentation"><topic>seg</topic><update_rate>20</update_rate>
<camera><segmentation_type>panoptic</segmentation_type><horizontal_fov>1.047</horizontal_fov>
<image><width>64</width><height>48</height></image></camera></sensor>
<sensor name="lensed" type="camera"><topic>lensed</topic><update_rate>20</update_rate>
<camera><horizontal_fov>1.047</horizontal_fov><image><width>64</width><height>48</height></image>
<distortion><k1>1.5</k1></distortion></camera></sensor>
<sensor name="snap" type="camera"><update_rate>0</update_rate><camera><triggered>true</triggered>
<trigger_topic>take</trigger_topic><image><width>32</width><height>24</height></image></camera>
</sensor>
</link></model>
</world></sdf>
"""

PROBE = """
import json, sys, time
import numpy as np
from launcher.bus import keys
from launcher.bus.node import Node
node = Node("probe", argv=[], space=keys.SIM)
got, states = {}, []
node.create_subscription("mujoco_sim/msg/RenderState", "/world/cam/render/state",
                         lambda m: states.append(list(m.cameras)))
node.spin(1.5)  # nobody watches a camera yet: the sim sends the renderer nothing
idle = len(states)
node.create_subscription("mujoco_sim/msg/Image", "/camera", lambda m: got.setdefault("rgb", m))
node.create_subscription("mujoco_sim/msg/Image", "/depth_camera",
                         lambda m: got.setdefault("depth", m))
node.create_subscription("mujoco_sim/msg/CameraInfo", "/camera_info",
                         lambda m: got.setdefault("info", m))
node.create_subscription("mujoco_sim/msg/Image", "/seg/labels_map",
                         lambda m: got.setdefault("seg", m))
node.create_subscription("mujoco_sim/msg/Image", "/lensed",
                         lambda m: got.setdefault("lensed", m))
metrics = []
node.create_subscription("mujoco_sim/msg/PerformanceSensorMetrics",
                         "/camera/performance_metrics", metrics.append)
snaps = []
node.create_subscription("mujoco_sim/msg/Image", "/world/cam/model/cam/link/link/sensor/snap/"
                         "image", lambda m: snaps.append(m.header.stamp.sec))
end = time.time() + 150  # (a busy machine renders slowly: the first frames may take long)
while len(got) < 5 and time.time() < end:
    node.spin_once(0.1)
if len(got) < 5:
    sys.exit(f"no frame within 150 s from: {sorted({'rgb', 'depth', 'info', 'seg', 'lensed'} - set(got))}")
node.spin(1.0)
before = len(snaps)
take = node.create_publisher("mujoco_sim/msg/Boolean", "/take")
node.spin(0.5)
take.publish(node.message("mujoco_sim/msg/Boolean", data=True))
node.spin(3.0)
rgb = np.frombuffer(bytes(got["rgb"].data), np.uint8).reshape(48, 64, 3)
depth = np.frombuffer(bytes(got["depth"].data), np.float32).reshape(48, 64)
seg = np.frombuffer(bytes(got["seg"].data), np.uint8).reshape(48, 64, 3)
lensed = np.frombuffer(bytes(got["lensed"].data), np.uint8).reshape(48, 64, 3)
red = lambda picture: int(((picture[..., 0] > 120) & (picture[..., 1] < 90)).sum())
print(json.dumps({"idle": idle, "seg": [seg[24, 32].tolist(), seg[1, 1].tolist()],
                  "red": [red(rgb), red(lensed)], "centre": rgb[24, 32].tolist(), "corner": rgb[1, 1].tolist(),
                  "depth": float(depth[24, 32]), "depth_corner": str(depth[1, 1]),
                  "encoding": [got["rgb"].encoding, got["depth"].encoding],
                  "frame": got["rgb"].header.frame_id, "k": list(got["info"].k),
                  "snaps": [before, len(snaps)],
                  "metrics": [[m.name, m.nominal_update_rate, m.sim_update_rate, m.fps]
                              for m in metrics[-1:]]}))
node.destroy_node()
"""


def test_cameras_draw_what_is_there_in_a_renderer_of_their_own(sensor_ws):
    """A camera looking at a red box has red pixels where it projects; a depth pixel reads
    the metric distance to the box's face; camera_info's K follows the field of view; the sim
    sends the renderer nothing while nobody watches; a triggered camera draws once a trigger."""
    import json
    import subprocess
    import sys

    sensor_ws.write("cam.sdf", CAMERA_WORLD)
    proc = sensor_ws.start("gz", "sim", "-s", "-r", "-v", "3", "cam.sdf", output="sim.out")
    try:
        sensor_ws.wait_for_output("running", 60, "sim.out")
        probe = sensor_ws.write("probe.py", PROBE)
        done = subprocess.run([sys.executable, str(probe)], env=sensor_ws.env,
                              capture_output=True, text=True, timeout=240)
        assert done.returncode == 0, done.stderr
        seen = json.loads(done.stdout.splitlines()[-1])
        assert seen["idle"] == 0
        r, g, b = seen["centre"]
        assert r > 120 and g < 90 and b < 90, seen  # the red box, lit
        assert seen["corner"] == [0, 0, 0]  # nothing there
        assert seen["depth"] == pytest.approx(2.5, abs=0.01)  # the face is 2.5 m ahead
        assert seen["depth_corner"] == "inf"
        assert seen["encoding"] == ["rgb8", "32FC1"] and seen["frame"] == "cam::link::camera"
        fx = 64 / (2 * math.tan(1.047 / 2))
        assert seen["k"] == pytest.approx([fx, 0, 32, 0, fx, 24, 0, 0, 1])
        assert seen["snaps"] == [0, 1], seen  # one frame, for the one trigger
        # a pincushion lens draws the box larger, about the centre
        plain_red, lensed_red = seen["red"]
        assert lensed_red > 1.1 * plain_red > 0, seen
        # the labelled box in the panoptic map: instance 1 of label 40; elsewhere background
        assert seen["seg"] == [[1, 0, 40], [0, 0, 0]], seen
        # <enable_metrics>: the renderer gives the frames' rate in sim time and real time
        [[name, nominal, sim_rate, fps]] = seen["metrics"]
        assert name == "cam::link::camera" and nominal == 20 and fps > 0, seen
        assert sim_rate == pytest.approx(20, rel=0.01) or sim_rate < 20, seen  # (drops)
        assert "drawing the cameras of world 'cam' with egl" in sensor_ws.output("sim.out")
    finally:
        assert stop(proc) == 0


def test_ros_gz_sim_demos_camera_launch_bridges_images_unchanged(sensor_ws):
    demos_workspace(sensor_ws)
    proc = sensor_ws.start("launch", "ros_gz_sim_demos", "camera.launch.py", "rviz:=false",
                           output="demo.out")
    try:
        sensor_ws.wait_for_output("bridging 2 of 2 entries", 60, "demo.out")
        image = sensor_ws.run("topic", "echo", "/camera", "sensor_msgs/msg/Image", "--once",
                              "--no-arr", "--timeout", "60", timeout=90)
        assert image.returncode == 0, image.stderr + sensor_ws.output("demo.out")
        assert "width: 320" in image.stdout and "height: 240" in image.stdout
        assert "encoding: rgb8" in image.stdout and "length: 230400" in image.stdout
        info = sensor_ws.run("topic", "echo", "/camera_info", "sensor_msgs/msg/CameraInfo",
                             "--once", "--field", "k", "--timeout", "60", timeout=90)
        assert info.returncode == 0 and "277.1" in info.stdout, info.stdout + info.stderr
        gz = sensor_ws.run("gz", "topic", "-e", "-t", "/camera", "-n", "1", timeout=60)
        assert "pixel_format_type: RGB_INT8" in gz.stdout, gz.stdout[:500]
    finally:
        assert stop(proc) == 130


def test_ros_gz_image_image_bridge_carries_images_to_ros(sensor_ws):
    sensor_ws.write("cam.sdf", CAMERA_WORLD)
    sensor_ws.write("images.launch.yaml", """
    launch:
      - executable: {cmd: "gz sim -s -r cam.sdf", output: screen}
      - node: {pkg: ros_gz_image, exec: image_bridge, args: "/camera /depth_camera",
               output: screen}
    """)
    proc = sensor_ws.start("launch", "images.launch.yaml", output="launch.out")
    try:
        sensor_ws.wait_for_output("bridging 2 of 2 entries", 60, "launch.out")
        depth = sensor_ws.run("topic", "echo", "/depth_camera", "sensor_msgs/msg/Image",
                              "--once", "--no-arr", "--timeout", "60", timeout=90)
        assert depth.returncode == 0, depth.stderr
        assert "encoding: 32FC1" in depth.stdout and "width: 64" in depth.stdout
        bad = sensor_ws.run("run", "ros_gz_image", "image_bridge", timeout=60)
        assert bad.returncode == 1 and "name the image topics to bridge" in bad.stderr
    finally:
        assert stop(proc) == 130


CLASSIC = ("external", "gazebo_plugins", "worlds")  # in ../shared


def test_gazebo_plugins_ray_sensor_demo_publishes_onto_the_ros_graph(sensor_ws):
    """gazebo_plugins' classic world, unchanged: its eight gazebo_ros_ray_sensor plugins
    publish straight onto the ROS graph, read by a ROS subscriber."""
    world = str(shared(*CLASSIC, "gazebo_ros_ray_sensor_demo.world"))
    proc = sensor_ws.start("gz", "sim", "-s", "-r", "-v", "3", world, output="sim.out")
    try:
        sensor_ws.wait_for_output("running", 60, "sim.out")
        listed = sensor_ws.run("topic", "list", "-t").stdout
        for family in ("ray", "gpu_ray"):
            for name, type_name in (("laserscan", "LaserScan"), ("pointcloud", "PointCloud"),
                                    ("pointcloud2", "PointCloud2"), ("range", "Range")):
                assert f"/{family}/{name} [sensor_msgs/msg/{type_name}]" in listed, listed
        near = sensor_ws.run("topic", "echo", "/ray/range", "--once", "--timeout", "60",
                             timeout=90)
        found = re.search(r"\nrange: ([\d.]+)", near.stdout)
        # the sensor 1.5 m behind the box's centre, the box 0.1 m deep: 1.45 m to its face
        assert found and float(found.group(1)) == pytest.approx(1.45, abs=0.01), near.stdout
        assert "frame_id: ray_link" in near.stdout
        scan = sensor_ws.run("topic", "echo", "/gpu_ray/laserscan", "--once", "-f", "--field",
                             "ranges", "--timeout", "60", timeout=90)
        ranges = [float(v.replace(".inf", "inf"))  # YAML writes infinity .inf
                  for v in re.findall(r"^- (\S+)$", scan.stdout, re.M)]
        assert len(ranges) == 300 and ranges[150] == pytest.approx(1.45, abs=0.01)
    finally:
        assert stop(proc) == 0


def test_gazebo_plugins_camera_demo_publishes_images_onto_the_ros_graph(sensor_ws):
    world = str(shared(*CLASSIC, "gazebo_ros_camera_demo.world"))
    proc = sensor_ws.start("gz", "sim", "-s", "-r", "-v", "3", world, output="sim.out")
    try:
        sensor_ws.wait_for_output("running", 60, "sim.out")
        image = sensor_ws.run("topic", "echo", "/demo_cam/camera1/image_raw", "--once",
                              "--no-arr", "--timeout", "60", timeout=90)
        assert image.returncode == 0, image.stderr
        assert "width: 640" in image.stdout and "height: 480" in image.stdout
        assert "frame_id: camera_link" in image.stdout and "encoding: rgb8" in image.stdout
        info = sensor_ws.run("topic", "echo", "/demo_cam/camera1/camera_info", "--once",
                             "--field", "k", "--timeout", "60", timeout=90)
        # fx = 640 / (2 tan(1.3962634 / 2))
        assert f"{640 / (2 * math.tan(1.3962634 / 2)):.3f}"[:6] in info.stdout, info.stdout
    finally:
        assert stop(proc) == 0


DEPTH_BGR_WORLD = """<?xml version="1.0"?>
<sdf version="1.6"><world name="depth_bgr">
<model name="cam"><static>true</static><pose>0 0 0.5 0 0 0</pose><link name="camera_link">
<sensor type="depth" name="depth1"><update_rate>10</update_rate>
<camera name="head"><horizontal_fov>1.0</horizontal_fov>
<image><width>64</width><height>48</height><format>B8G8R8</format></image>
<clip><near>0.05</near><far>20</far></clip></camera>
<plugin name="depth_controller" filename="libgazebo_ros_camera.so">
<ros><namespace>bgr</namespace></ros><camera_name>depth1</camera_name>
<frame_name>camera_link</frame_name></plugin></sensor></link></model>
</world></sdf>
"""


def test_gazebo_ros_depth_cameras_colour_image_is_written_in_its_format(sensor_ws):
    """gazebo_ros's camera plugin on a depth camera: the colour image's encoding is the one
    <image><format> names (B8G8R8: bgr8), as for a plain camera."""
    sensor_ws.write("depth_bgr.world", DEPTH_BGR_WORLD)
    proc = sensor_ws.start("gz", "sim", "-s", "-r", "-v", "3", "depth_bgr.world",
                           output="sim.out")
    try:
        sensor_ws.wait_for_output("running", 60, "sim.out")
        image = sensor_ws.run("topic", "echo", "/bgr/depth1/image_raw", "--once", "--no-arr",
                              "--timeout", "60", timeout=90)
        assert image.returncode == 0, image.stderr
        assert "encoding: bgr8" in image.stdout and "width: 64" in image.stdout, image.stdout
        depth = sensor_ws.run("topic", "echo", "/bgr/depth1/depth/image_raw", "--once",
                              "--no-arr", "--timeout", "60", timeout=90)
        assert "encoding: 32FC1" in depth.stdout, depth.stdout + depth.stderr
    finally:
        assert stop(proc) == 0


FLOOD_WORLD = """<?xml version="1.0"?>
<sdf version="1.9"><world name="flood">
<plugin filename="gz-sim-sensors-system" name="gz::sim::systems::Sensors"/>
<model name="wall"><static>true</static><pose>3 0 1 0 0 0</pose><link name="l"><collision
name="c"><geometry><box><size>0.2 20 4</size></box></geometry></collision></link></model>
<model name="bot"><static>true</static><pose>0 0 1 0 0 0</pose><link name="link">
<sensor name="lidar" type="gpu_lidar"><topic>lidar</topic><update_rate>50</update_rate>
<lidar><scan><horizontal><samples>1800</samples><min_angle>-3.14</min_angle>
<max_angle>3.14</max_angle></horizontal><vertical><samples>16</samples>
<min_angle>-0.2</min_angle><max_angle>0.2</max_angle></vertical></scan>
<range><min>0.1</min><max>30</max></range></lidar></sensor></link></model>
</world></sdf>
"""

STALLER = """
import time
from launcher.bus import keys
from launcher.bus.node import Node
node = Node("staller", argv=[], space=keys.SIM)
got = []
node.create_subscription("mujoco_sim/msg/PointCloudPacked", "/lidar/points",
                         lambda payload: got.append(1), raw=True)
while not got:
    node.spin_once(0.1)
print("reading", flush=True)
node.spin()
"""

CLOCK_WATCH = """
import json, struct, sys, time
from launcher.bus import keys
from launcher.bus.node import Node
node = Node("clock_watch", argv=[], space=keys.SIM)
clocks = []
layout = struct.Struct("<4xiI")
def on_clock(payload):
    sec, nanosec = layout.unpack_from(payload)
    clocks.append((time.monotonic(), sec + nanosec * 1e-9))
node.create_subscription("mujoco_sim/msg/Clock", "/world/flood/clock", on_clock, raw=True,
                         inline=True)
while not clocks:
    node.spin_once(0.1)
node.spin(float(sys.argv[1]))
(w0, s0), (w1, s1) = clocks[0], clocks[-1]
gap = max(b[0] - a[0] for a, b in zip(clocks, clocks[1:]))
print(json.dumps({"rtf": (s1 - s0) / (w1 - w0), "gap": gap}))
"""


def test_a_subscriber_that_never_reads_puts_no_back_pressure_on_the_sim(sensor_ws):
    """A process that subscribes to the lidar's point clouds (about 0.9 MB at 50 Hz) and
    then stops (SIGSTOP: it never reads again) fills its socket; the sim drops what it
    cannot take (as rmw_zenoh does for keep-last topics) and steps on at its pace: no stall,
    and its RTF as it was before (same run)."""
    import json
    import subprocess
    import sys

    sensor_ws.write("flood.sdf", FLOOD_WORLD)
    staller_script = sensor_ws.write("staller.py", STALLER)
    watch = sensor_ws.write("watch.py", CLOCK_WATCH)
    sim = sensor_ws.start("gz", "sim", "-s", "-r", "-v", "3", "flood.sdf", output="sim.out")
    staller = None
    try:
        sensor_ws.wait_for_output("running", 60, "sim.out")

        def watch_clock(seconds: float) -> dict:
            done = subprocess.run([sys.executable, str(watch), str(seconds)], env=sensor_ws.env,
                                  capture_output=True, text=True, timeout=120)
            assert done.returncode == 0, done.stderr
            return json.loads(done.stdout.splitlines()[-1])

        before = watch_clock(6)
        staller = subprocess.Popen([sys.executable, str(staller_script)], env=sensor_ws.env,
                                   stdout=subprocess.PIPE, text=True)
        assert staller.stdout.readline().strip() == "reading"
        staller.send_signal(signal.SIGSTOP)
        stalled = watch_clock(12)  # Zenoh would give up on a blocked link after 5 s
        assert stalled["gap"] < 1.0, (before, stalled)  # the sim never waited on it
        assert stalled["rtf"] >= 0.95 * before["rtf"], (before, stalled)
    finally:
        if staller is not None:
            staller.kill()
            staller.wait(10)
        assert stop(sim) == 0
