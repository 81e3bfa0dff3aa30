"""Robot descriptions that several tests read: a URDF chain, SDF robots."""

from __future__ import annotations

CHAIN = """<robot name="arm">
  <link name="base"/><link name="l1"/><link name="l2"/><link name="l3"/><link name="tool"/>
  <link name="finger_a"/><link name="finger_b"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="l1"/>
    <origin xyz="0 0 1" rpy="0 0 0"/><axis xyz="0 0 1"/></joint>
  <joint name="j2" type="continuous"><parent link="l1"/><child link="l2"/>
    <origin xyz="0.5 0 0" rpy="0 0 1.5707963267948966"/><axis xyz="0 1 0"/></joint>
  <joint name="j3" type="prismatic"><parent link="l2"/><child link="l3"/>
    <origin xyz="0.2 0.1 0" rpy="0.7853981633974483 0 0"/><axis xyz="1 0 0"/></joint>
  <joint name="tool_mount" type="fixed"><parent link="l3"/><child link="tool"/>
    <origin xyz="0 0 0.05" rpy="0 0 0"/></joint>
  <joint name="fa" type="prismatic"><parent link="tool"/><child link="finger_a"/>
    <axis xyz="0 1 0"/></joint>
  <joint name="fb" type="prismatic"><parent link="tool"/><child link="finger_b"/>
    <axis xyz="0 1 0"/><mimic joint="fa" multiplier="-1" offset="0.01"/></joint>
</robot>"""


SDF_ROBOT = """<?xml version="1.0"?>
<sdf version="1.9"><model name="pendulum">
  <!-- an SDF 1.4 file would give axes in the model frame -->
  <link name="base"><pose>0 0 1 0 0 0</pose></link>
  <link name="arm"><pose>0 0.2 1 0 0 1.5707963</pose></link>
  <link name="tip"><pose>0 0.2 0.5 0 0 1.5707963</pose></link>
  <joint name="to_world" type="fixed"><parent>world</parent><child>base</child></joint>
  <joint name="hinge" type="revolute"><parent>base</parent><child>arm</child>
    <axis><xyz>1 0 0</xyz><limit><lower>-1</lower><upper>1</upper></limit></axis></joint>
  <joint name="spin" type="revolute"><parent>arm</parent><child>tip</child>
    <axis><xyz>0 0 1</xyz></axis></joint>
</model></sdf>"""


CLASSIC_ROBOT = """<robot name="bot">
  <link name="base_link"><inertial><mass value="2"/><inertia ixx="0.02" iyy="0.02" izz="0.02"
    ixy="0" ixz="0" iyz="0"/></inertial><collision><origin xyz="0 0 0.09"/><geometry>
    <box size="0.3 0.2 0.06"/></geometry></collision></link>
  <link name="caster"><inertial><mass value="0.05"/><inertia ixx="1e-5" iyy="1e-5" izz="1e-5"
    ixy="0" ixz="0" iyz="0"/></inertial><collision><geometry><sphere radius="0.025"/></geometry>
    </collision></link>
  <joint name="caster_joint" type="fixed"><parent link="base_link"/><child link="caster"/>
    <origin xyz="-0.12 0 0.025"/></joint>
  {wheels}
  <gazebo reference="caster"><mu1>0.0</mu1></gazebo>
  <gazebo><plugin filename="libgazebo_ros_diff_drive.so" name="diff_drive">{params}</plugin>
  </gazebo>
</robot>"""


WHEEL = """<link name="{side}_wheel"><inertial><mass value="0.2"/><inertia ixx="2e-4" iyy="2e-4"
  izz="3e-4" ixy="0" ixz="0" iyz="0"/></inertial><collision><geometry>
  <cylinder radius="0.05" length="0.02"/></geometry></collision></link>
  <joint name="{side}_wheel_joint" type="continuous"><parent link="base_link"/>
  <child link="{side}_wheel"/><origin xyz="0 {y} 0.05" rpy="-1.5707963 0 0"/>
  <axis xyz="0 0 1"/></joint>"""


# A fixed arm of revolute links under ros2_control (gz_ros2_control in the sim; replace its
# plugin by mock_components/GenericSystem for ros2_control_node): its joints j1-j4, whose
# interfaces are the ros2_control tests', {links} from arm_links(4), {yaml} its controllers.
ARM = """<?xml version="1.0"?>
<robot name="arm">
  <link name="world"/>
  <link name="base"><inertial><mass value="5"/><inertia ixx="1" iyy="1" izz="1" ixy="0"
    ixz="0" iyz="0"/></inertial></link>
  <joint name="fix" type="fixed"><parent link="world"/><child link="base"/>
    <origin xyz="0 0 0.5"/></joint>
  {links}
  <ros2_control name="ArmSystem" type="system">
    <hardware><plugin>gz_ros2_control/GazeboSimSystem</plugin></hardware>
    <joint name="j1"><command_interface name="position"><param name="min">-2</param>
      <param name="max">2</param></command_interface>
      <state_interface name="position"/><state_interface name="velocity"/>
      <state_interface name="effort"/></joint>
    <joint name="j2"><command_interface name="position"/>
      <state_interface name="position"/><state_interface name="velocity"/></joint>
    <joint name="j3"><command_interface name="velocity"/>
      <state_interface name="position"/><state_interface name="velocity"/></joint>
    <joint name="j4"><command_interface name="effort"/>
      <state_interface name="position"/><state_interface name="velocity"/></joint>
  </ros2_control>
  <gazebo><plugin filename="gz_ros2_control-system"
    name="gz_ros2_control::GazeboSimROS2ControlPlugin">
    <parameters>{yaml}</parameters></plugin></gazebo>
</robot>
"""
LINK = """<link name="l{n}"><inertial><mass value="1"/><inertia ixx="0.1" iyy="0.1" izz="0.1"
  ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="j{n}" type="revolute"><parent link="{parent}"/><child link="l{n}"/>
    <origin xyz="0 0 0.1"/><axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="50"
    velocity="5"/><dynamics damping="0.5"/></joint>"""


def arm_links(count: int) -> str:
    """ARM's links l1…l<count>, each on the one before (the first on base)."""
    return "\n  ".join(LINK.format(n=n, parent="base" if n == 1 else f"l{n - 1}")
                        for n in range(1, count + 1))
