"""gazebo_ros's classic plugins in URDF `<gazebo>` tags, with their ROS 1 and ROS 2 parameters.

They speak ROS directly (on the ROS graph, not the sim's own side), as in Gazebo classic:
`libgazebo_ros_diff_drive.so` subscribes geometry_msgs/Twist on `cmd_vel` and publishes
nav_msgs/Odometry on `odom` (and odom → base on /tf),
`libgazebo_ros_joint_state_publisher.so` publishes sensor_msgs/JointState on `joint_states`,
each in the plugin's namespace (ROS 1 `robotNamespace`, ROS 2
`<ros><namespace>`, and ROS 2 `<remapping>from:=to</remapping>`).

ROS 1 names: leftJoint, rightJoint, wheelSeparation, wheelDiameter, torque, commandTopic,
odometryTopic, odometryFrame, robotBaseFrame, publishOdomTF, updateRate; jointName (comma
separated). ROS 2: left_joint, right_joint, wheel_separation, wheel_diameter,
max_wheel_torque, publish_odom, publish_odom_tf, odometry_frame, robot_base_frame,
update_rate; joint_name.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from typing import Any

from launcher.records import dataclass, replace
from launcher.schema import Kind, attr
from launcher.sim.plugins.diff_drive import DiffDrive
from launcher.sim.plugins.gazebo_ros import under
from launcher.sim.plugins.joint_state import JointStatePublisher
from launcher.sim.plugins.odometry import yaw_quat

# the gz name each classic parameter feeds: (ROS 1, ROS 2) -> gz
DIFF_DRIVE = {("leftJoint", "left_joint"): "left_joint",
              ("rightJoint", "right_joint"): "right_joint",
              ("wheelSeparation", "wheel_separation"): "wheel_separation",
              ("torque", "max_wheel_torque"): "max_wheel_torque",
              ("updateRate", "update_rate"): "odom_publish_frequency"}


@dataclass
class ClassicDiffDriveParameters:
    """libgazebo_ros_diff_drive.so's parameters, ROS 1's and ROS 2's (`ros` holds ROS 2's
    namespace and remappings); the ones the sim has no use for are accepted quietly."""

    leftJoint: list[str] = attr(Kind.NAMES)  # noqa: N815 - ROS 1's spelling
    rightJoint: list[str] = attr(Kind.NAMES)  # noqa: N815
    wheelSeparation: float | None = attr(Kind.FLOAT, None, above=0.0)  # noqa: N815
    wheelDiameter: float | None = attr(Kind.FLOAT, None, above=0.0)  # noqa: N815
    torque: float | None = attr(Kind.FLOAT, None, minimum=0.0)
    wheelTorque: float | None = attr(Kind.FLOAT, None, minimum=0.0)  # noqa: N815
    wheelAcceleration: float | None = attr(Kind.FLOAT, None)  # noqa: N815
    commandTopic: str = attr(Kind.TEXT, "")  # noqa: N815
    odometryTopic: str = attr(Kind.TEXT, "")  # noqa: N815
    odometryFrame: str = attr(Kind.TEXT, "")  # noqa: N815
    robotBaseFrame: str = attr(Kind.TEXT, "")  # noqa: N815
    odometrySource: str = attr(Kind.TEXT, "")  # noqa: N815
    publishOdomTF: bool | None = attr(Kind.BOOL, None)  # noqa: N815
    publishWheelTF: bool = attr(Kind.BOOL, False)  # noqa: N815
    publishWheelJointState: bool = attr(Kind.BOOL, False)  # noqa: N815
    publishTf: bool = attr(Kind.BOOL, True)  # noqa: N815
    updateRate: float | None = attr(Kind.FLOAT, None, minimum=0.0)  # noqa: N815
    robotNamespace: str = attr(Kind.TEXT, "")  # noqa: N815
    rosDebugLevel: str = attr(Kind.TEXT, "")  # noqa: N815
    legacyMode: bool = attr(Kind.BOOL, False)  # noqa: N815
    left_joint: list[str] = attr(Kind.NAMES)
    right_joint: list[str] = attr(Kind.NAMES)
    wheel_separation: list[str] = attr(Kind.NAMES)  # several pairs in ROS 2
    wheel_diameter: list[str] = attr(Kind.NAMES)
    max_wheel_torque: float | None = attr(Kind.FLOAT, None, minimum=0.0)
    max_wheel_acceleration: float | None = attr(Kind.FLOAT, None)
    num_wheel_pairs: int = attr(Kind.INT, 1, minimum=1)
    publish_odom: bool = attr(Kind.BOOL, True)
    publish_odom_tf: bool | None = attr(Kind.BOOL, None)
    publish_wheel_tf: bool = attr(Kind.BOOL, False)
    odometry_frame: str = attr(Kind.TEXT, "")
    robot_base_frame: str = attr(Kind.TEXT, "")
    odometry_source: str = attr(Kind.TEXT, "")
    update_rate: float | None = attr(Kind.FLOAT, None, minimum=0.0)
    covariance_x: float = attr(Kind.FLOAT, 0.0)
    covariance_y: float = attr(Kind.FLOAT, 0.0)
    covariance_yaw: float = attr(Kind.FLOAT, 0.0)
    ros: str = attr(Kind.TEXT, "")


def _ros_topic(plugin: Any, ros1: str, default: str) -> str:
    """A classic plugin's topic: its own parameter or remapping, in its namespace."""
    element = plugin.config.element
    name = plugin.text(ros1) or default
    for remapping in element.iter("remapping"):
        source, _, target = (remapping.text or "").strip().partition(":=")
        if source.strip() == default and target.strip():
            name = target.strip()
    if name.startswith("/"):
        return name
    namespace = under(plugin.config.namespace, plugin.text("robotNamespace") or
                      (element.findtext("ros/namespace") or "")).strip("/")
    return f"/{namespace}/{name}" if namespace else f"/{name}"


class ClassicDiffDrive(DiffDrive):
    def prepare(self, spec: Any) -> None:
        self.classic = self.parameters(ClassicDiffDriveParameters)  # warns what it does not know
        self.config = replace(self.config, element=self._translated(self.config.element))
        self.unknown_parameters = "ignore"  # the classic names, said above
        super().prepare(spec)

    @staticmethod
    def _translated(element: ET.Element) -> ET.Element:
        out = ET.Element("plugin", dict(element.attrib))
        for child in element:
            out.append(child)
        for names, gz in DIFF_DRIVE.items():
            for name in (n for n in names if n != gz):
                for found in element.findall(name):
                    ET.SubElement(out, gz).text = found.text
        for name in ("wheelDiameter", "wheel_diameter"):
            diameter = element.findtext(name)
            if diameter:
                ET.SubElement(out, "wheel_radius").text = str(float(diameter) / 2)
        if element.find("updateRate") is None and element.find("update_rate") is None:
            ET.SubElement(out, "odom_publish_frequency").text = "50"
        return out

    def load(self) -> None:
        transport = self.sim.transport
        classic = self.classic
        self.frame_id = classic.odometryFrame or classic.odometry_frame or "odom"
        self.child_frame_id = classic.robotBaseFrame or classic.robot_base_frame or \
            "base_footprint"
        self.publish_odom = classic.publish_odom
        self.publish_tf = next((v for v in (classic.publishOdomTF, classic.publish_odom_tf)
                                if v is not None), True)
        self.odom_pub = transport.publisher("nav_msgs/msg/Odometry",
                                            _ros_topic(self, "odometryTopic", "odom"), ros=True)
        self.tf_pub = transport.publisher("tf2_msgs/msg/TFMessage", "/tf", ros=True)
        import numpy as np

        # the diagonal gazebo_ros_diff_drive reports: x, y, and yaw (the rest held fixed)
        self.covariance = np.zeros(36)
        self.covariance[[0, 7, 35]] = (classic.covariance_x, classic.covariance_y,
                                       classic.covariance_yaw)
        self.cmd_sub = transport.subscribe("geometry_msgs/msg/Twist",
                                           _ros_topic(self, "commandTopic", "cmd_vel"),
                                           self.on_cmd_vel, ros=True)

    def _publish(self, now: float) -> None:
        odom_wanted = self.publish_odom and self.odom_pub.get_subscription_count() > 0
        tf_wanted = self.publish_tf and self.tf_pub.get_subscription_count() > 0
        if not (odom_wanted or tf_wanted):
            return
        t = self.sim.transport
        header = t.header(now, self.frame_id)
        pose = t.pose(self.x, self.y, 0.0, yaw_quat(self.theta))
        if odom_wanted:
            twist = t.message("geometry_msgs/msg/Twist",
                              linear=t.vector(self.linear, 0.0, 0.0),
                              angular=t.vector(0.0, 0.0, self.angular))
            self.odom_pub.publish(t.message(
                "nav_msgs/msg/Odometry", header=header, child_frame_id=self.child_frame_id,
                pose=t.message("geometry_msgs/msg/PoseWithCovariance", pose=pose,
                               covariance=self.covariance),
                twist=t.message("geometry_msgs/msg/TwistWithCovariance", twist=twist,
                                covariance=self.covariance)))
        if tf_wanted:
            transform = t.message(
                "geometry_msgs/msg/Transform",
                translation=t.vector(self.x, self.y, 0.0), rotation=pose.orientation)
            self.tf_pub.publish(t.message("tf2_msgs/msg/TFMessage", transforms=[t.message(
                "geometry_msgs/msg/TransformStamped", header=header,
                child_frame_id=self.child_frame_id, transform=transform)]))


@dataclass
class ClassicJointStateParameters:
    """libgazebo_ros_joint_state_publisher.so's parameters, ROS 1's and ROS 2's."""

    jointName: str = attr(Kind.TEXT, "")  # noqa: N815 - ROS 1's, comma separated
    updateRate: float | None = attr(Kind.FLOAT, None, minimum=0.0)  # noqa: N815
    robotNamespace: str = attr(Kind.TEXT, "")  # noqa: N815
    topicName: str = attr(Kind.TEXT, "")  # noqa: N815
    joint_name: list[str] = attr(Kind.NAMES)
    update_rate: float = attr(Kind.FLOAT, 50.0, minimum=0.0)
    ros: str = attr(Kind.TEXT, "")


class ClassicJointStates(JointStatePublisher):
    declared = ClassicJointStateParameters  # type: ignore[assignment]

    def prepare(self, spec: Any) -> None:
        element = ET.Element("plugin", dict(self.config.element.attrib))
        element.extend(list(self.config.element))
        self.config = replace(self.config, element=element)
        names = [n.strip() for n in (element.findtext("jointName") or "").split(",")
                 if n.strip()]
        for name in names:
            ET.SubElement(element, "joint_name").text = name
        rate = element.findtext("updateRate")
        if rate:
            ET.SubElement(element, "update_rate").text = rate
        super().prepare(spec)

    def load(self) -> None:
        self.publisher = self.sim.transport.publisher(
            "sensor_msgs/msg/JointState", _ros_topic(self, "topicName", "joint_states"),
            ros=True)
        self.reset()

    def state(self, transport: Any, now: float, data: Any) -> Any:
        return transport.message(
            "sensor_msgs/msg/JointState", header=transport.header(now, ""), name=self.joints,
            position=data.qpos[self.qpos], velocity=data.qvel[self.dofs],
            effort=data.qfrc_actuator[self.dofs])
