"""ros2_controllers' controllers launcher provides, by the type names YAML files give them."""

from __future__ import annotations

import importlib

from launcher.control.controller import Controller

_HERE = "launcher.control.controllers"
TYPES = {
    "joint_state_broadcaster/JointStateBroadcaster":
        f"{_HERE}.joint_state_broadcaster:JointStateBroadcaster",
    "joint_trajectory_controller/JointTrajectoryController":
        f"{_HERE}.joint_trajectory:JointTrajectoryController",
    "forward_command_controller/ForwardCommandController":
        f"{_HERE}.forward_command:ForwardCommandController",
    "position_controllers/JointGroupPositionController":
        f"{_HERE}.forward_command:JointGroupPositionController",
    "velocity_controllers/JointGroupVelocityController":
        f"{_HERE}.forward_command:JointGroupVelocityController",
    "effort_controllers/JointGroupEffortController":
        f"{_HERE}.forward_command:JointGroupEffortController",
    "diff_drive_controller/DiffDriveController": f"{_HERE}.diff_drive:DiffDriveController",
    "tricycle_controller/TricycleController": f"{_HERE}.steering:TricycleController",
    "ackermann_steering_controller/AckermannSteeringController":
        f"{_HERE}.steering:AckermannSteeringController",
    "imu_sensor_broadcaster/IMUSensorBroadcaster":
        f"{_HERE}.sensor_broadcasters:IMUSensorBroadcaster",
    "force_torque_sensor_broadcaster/ForceTorqueSensorBroadcaster":
        f"{_HERE}.sensor_broadcasters:ForceTorqueSensorBroadcaster",
    "pose_broadcaster/PoseBroadcaster": f"{_HERE}.pose_broadcaster:PoseBroadcaster",
    "position_controllers/GripperActionController": f"{_HERE}.gripper:GripperActionController",
    "effort_controllers/GripperActionController":
        f"{_HERE}.gripper:EffortGripperActionController",
    "parallel_gripper_action_controller/GripperActionController":
        f"{_HERE}.gripper:ParallelGripperActionController",
}


def controller_class(type_name: str) -> type[Controller] | None:
    target = TYPES.get(type_name)
    if target is None:
        return None
    module, _, attribute = target.partition(":")
    return getattr(importlib.import_module(module), attribute)
