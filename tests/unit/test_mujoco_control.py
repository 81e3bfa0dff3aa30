"""mujoco_ros2_control's pieces without a bus: transmissions, PIDs, the MJCF's actuators as it
reads them, and MJCF includes."""

from __future__ import annotations

import mujoco
import pytest

from launcher.control.description import Transmission
from launcher.sim.mujoco_control.actuators import (
    MOTOR,
    PASSIVE,
    POSITION,
    VELOCITY,
    Pid,
    actuators_of,
    pids_from,
)
from launcher.sim.mujoco_control.transmissions import Coupling

ARM = """<mujoco>
  <worldbody>
    <body><joint name="a" axis="0 1 0"/><geom size="0.1"/>
      <body><joint name="b" axis="0 1 0"/><geom size="0.1"/>
        <body><joint name="c" axis="0 1 0"/><geom size="0.1"/>
          <body><joint name="d" type="slide"/><geom size="0.1"/></body></body></body></body>
  </worldbody>
  <actuator>
    <position name="a" joint="a" kp="10"/>
    <velocity name="b" joint="b" kv="10"/>
    <motor name="c" joint="c"/>
  </actuator>
</mujoco>"""


def test_actuators_are_classified_by_their_bias_and_unactuated_joints_are_passive():
    model = mujoco.MjModel.from_xml_string(ARM)
    kinds = {a.joint: a.kind for a in actuators_of(model, "arm.xml")}
    assert kinds == {"a": POSITION, "b": VELOCITY, "c": MOTOR, "d": PASSIVE}


def test_a_differential_transmission_goes_there_and_back():
    coupling = Coupling(Transmission("t", "transmission_interface/DifferentialTransmission",
                                     [("joint1", "joint1", 2.0, 0.1),
                                      ("joint2", "joint2", 0.5, -0.2)],
                                     [("actuator1", "actuator1", 1.0),
                                      ("actuator2", "actuator2", 1.0)]))
    joints = [(0.3, 1.0, 5.0), (-0.4, -2.0, 7.0)]
    back = coupling.to_joints([tuple(a) for a in coupling.to_actuators(joints)])
    assert back == [pytest.approx(list(j)) for j in joints]


def test_a_simple_transmission_scales_by_its_reduction_and_offset():
    coupling = Coupling(Transmission("t", "transmission_interface/SimpleTransmission",
                                     [("j", "", 10.0, 0.5)], [("m", "", 1.0)]))
    assert coupling.to_actuators([(1.5, 2.0, 30.0)]) == [[10.0, 20.0, 3.0]]


def test_a_pid_clamps_its_integral_and_its_output():
    pid = Pid(p=1.0, i=10.0, i_clamp_max=0.5, i_clamp_min=-0.5, u_clamp_max=2.0,
              u_clamp_min=-2.0)
    assert pid.compute(1.0, 0.1) == pytest.approx(1.5)  # p 1 + integral 0.5 (clamped)
    assert pid.compute(10.0, 0.1) == 2.0


def test_pid_gains_are_read_by_mode_and_joint_and_a_wrong_gain_is_named():
    pids = pids_from({"pid_gains.position.a.p": 5.0, "pid_gains.position.a.d": 1.0,
                      "other": 1})
    assert pids["position"]["a"].p == 5.0 and pids["position"]["a"].d == 1.0
    with pytest.raises(Exception, match="'q' is not a PID gain"):
        pids_from({"pid_gains.position.a.q": 1.0})


def test_an_mjcf_includes_a_file_beside_it_when_read_from_text(tmp_path):
    from launcher.sim.loading import load_world_file

    (tmp_path / "robot").mkdir()
    (tmp_path / "robot" / "arm.xml").write_text(ARM)
    (tmp_path / "scenes").mkdir()
    scene = tmp_path / "scenes" / "scene.xml"
    scene.write_text('<mujoco model="scene"><include file="../robot/arm.xml"/></mujoco>')
    spec = load_world_file(scene).spec
    assert spec.compile().njnt == 4


def test_a_missing_include_says_where_it_looked(tmp_path):
    from launcher.errors import LaunchError
    from launcher.sim.loading import load_world_file

    scene = tmp_path / "scene.xml"
    scene.write_text('<mujoco><include file="nowhere.xml"/></mujoco>')
    with pytest.raises(LaunchError, match=r'<include file="nowhere.xml">: no such file'):
        load_world_file(scene)


def test_a_missing_include_is_said_at_its_line_and_column_in_the_file_that_has_it(tmp_path):
    from launcher.errors import LaunchError
    from launcher.sim.loading import load_world_file

    (tmp_path / "robot.xml").write_text('<mujoco>\n  <worldbody/>\n    <include file="gone.xml"/>'
                                        '\n</mujoco>')
    scene = tmp_path / "scene.xml"
    scene.write_text('<mujoco><include file="robot.xml"/></mujoco>')
    with pytest.raises(LaunchError) as raised:
        load_world_file(scene)
    assert str(raised.value).startswith(f"{tmp_path / 'robot.xml'}:3:5: <include "
                                        'file="gone.xml">: no such file')
