"""Gazebo's sensors, simulated in MuJoCo.

An SDF `<sensor>` (in a world's or a spawned model's link) becomes a site on the link's body at
the sensor's pose, and a sensor plugin of the link's entity (sensors/base.py): scheduled in sim
time at its `update_rate`, doing work only while someone subscribes (or with `<always_on>`),
and publishing Gazebo's message, on Gazebo's topic, on the sim's side of the bus. As in gz-sim,
a sensor publishes only when the world loads its system (gz-sim-imu-system for an imu, …,
gz-sim-sensors-system for the rendering ones); a world that declares none (an MJCF world,
launcher's built-in empty world) runs them all.
"""

from __future__ import annotations

# SDF's sensor types (and classic Gazebo's names for them) → the kind launcher simulates
KINDS = {
    "imu": "imu", "magnetometer": "magnetometer", "altimeter": "altimeter",
    "air_pressure": "air_pressure", "navsat": "navsat", "gps": "navsat",
    "gpu_lidar": "lidar", "lidar": "lidar", "gpu_ray": "lidar", "ray": "lidar",
    "camera": "camera", "depth_camera": "depth_camera", "depth": "depth_camera",
    "rgbd_camera": "rgbd_camera", "rgbd": "rgbd_camera",
    "segmentation_camera": "segmentation_camera", "segmentation": "segmentation_camera",
    "force_torque": "force_torque", "contact": "contact", "air_speed": "air_speed",
}
# Kinds whose module is not there yet, or that MuJoCo cannot give: said at the sensor's line
NOT_SIMULATED = {
    "multicamera": "multicameras are not rendered yet",
    "wideanglecamera": "wide-angle cameras are not rendered",
    "wide_angle_camera": "wide-angle cameras are not rendered",
    "thermal_camera": "MuJoCo has no temperatures to render: no thermal image",
    "thermal": "MuJoCo has no temperatures to render: no thermal image",
    "logical_camera": "the logical camera's model list is not produced",
    "boundingbox_camera": "no bounding boxes are produced",
    "air_flow": "there is no air flow",
    "sonar": "sonar is not simulated", "rfid": "RFID is not simulated",
    "rfidtag": "RFID is not simulated", "wireless_receiver": "radio is not simulated",
    "wireless_transmitter": "radio is not simulated", "dvl": "the DVL is not simulated",
    "custom": "a custom sensor has no model here",
}
# The world system each kind needs, by its canonical file name (plugins.canonical)
SYSTEMS = {
    "imu": "gz-sim-imu-system", "magnetometer": "gz-sim-magnetometer-system",
    "altimeter": "gz-sim-altimeter-system", "air_pressure": "gz-sim-air-pressure-system",
    "navsat": "gz-sim-navsat-system", "lidar": "gz-sim-sensors-system",
    "force_torque": "gz-sim-forcetorque-system", "contact": "gz-sim-contact-system",
    "air_speed": "gz-sim-air-speed-system",
    **dict.fromkeys(("camera", "depth_camera", "rgbd_camera", "segmentation_camera"),
                    "gz-sim-sensors-system"),
}
# ... and the same systems by their class names (a world may name them only so)
SYSTEM_CLASSES = {
    "gz-sim-imu-system": "Imu", "gz-sim-magnetometer-system": "Magnetometer",
    "gz-sim-altimeter-system": "Altimeter", "gz-sim-air-pressure-system": "AirPressure",
    "gz-sim-navsat-system": "NavSat", "gz-sim-sensors-system": "Sensors",
    "gz-sim-forcetorque-system": "ForceTorque", "gz-sim-contact-system": "Contact",
    "gz-sim-air-speed-system": "AirSpeed", "gz-sim-cpu-lidar-system": "CpuLidar",
}
# SDF types that either of two systems runs: gz-sim 9 runs a CPU `lidar` (`ray`) in a system
# of its own (gz-sim-cpu-lidar-system); earlier ones, and launcher, with the rendering sensors
ALSO_RUN_BY = dict.fromkeys(("lidar", "ray"), "gz-sim-cpu-lidar-system")
CLASSES = {
    "imu": "launcher.sim.sensors.inertial:Imu",
    "magnetometer": "launcher.sim.sensors.inertial:Magnetometer",
    "altimeter": "launcher.sim.sensors.atmosphere:Altimeter",
    "air_pressure": "launcher.sim.sensors.atmosphere:AirPressure",
    "navsat": "launcher.sim.sensors.navsat:NavSat",
    "lidar": "launcher.sim.sensors.lidar:Lidar",
    "force_torque": "launcher.sim.sensors.force_torque:ForceTorque",
    "contact": "launcher.sim.sensors.contact:Contact",
    "air_speed": "launcher.sim.sensors.atmosphere:AirSpeed",
    **dict.fromkeys(("camera", "depth_camera", "rgbd_camera", "segmentation_camera"),
                    "launcher.sim.sensors.camera:Camera"),
}
