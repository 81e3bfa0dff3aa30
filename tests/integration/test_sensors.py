"""Gazebo's sensor worlds and ros_gz_sim_demos' sensor launch files, unchanged, on launcher's
sim: real processes (the sim, the bridge, the CLI) on a real router. What Gazebo publishes is
read with `gz topic -e`, what the bridge makes of it with a ROS subscriber."""

from __future__ import annotations

import re
import signal
import time

import pytest

from tests.conftest import shared
from tests.integration.test_gazebo import demos_workspace

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
        assert "length: 10240" in scan.stdout  # 640 × 16 rays
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
        said = sensor_ws.output("sim.out")
        assert "sensors.sdf:156: sensor 'air_speed' (type air_speed) is not simulated" in said
    finally:
        assert stop(proc) == 0
