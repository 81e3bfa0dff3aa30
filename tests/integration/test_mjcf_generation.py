"""mujoco_ros2_control's URDF-to-MJCF tools as `ros2 run` runs them: real xacro, real
MuJoCo, real files. The models are compared with what mujoco_ros2_control's own converter
made of the same inputs (recorded: tests/data/mjcf_generation/README.md)."""

from __future__ import annotations

import shutil
import struct
from pathlib import Path

import mujoco
import numpy as np
import pytest

from tests.support.environment import shared

DEMOS = ("external", "mujoco_ros2_control", "mujoco_ros2_control_demos")  # in ../shared
RECORDED = Path(__file__).resolve().parent.parent / "data" / "mjcf_generation"
TOOL = ("run", "mujoco_ros2_control", "make_mjcf_from_robot_description.py")


@pytest.fixture
def demo_ws(ws):
    ws.own_bus().env["LAUNCHER_PACKAGE_PATH"] = str(shared(*DEMOS))
    return ws


def resources() -> Path:
    return shared(*DEMOS, "demo_resources")


def expanded(ws, use_pid: str) -> Path:
    done = ws.run("run", "xacro", "xacro", str(resources() / "robot" / "test_robot.urdf"),
                  f"use_pid:={use_pid}", "use_mjcf_from_topic:=true",
                  "use_transmissions:=false", "headless:=true")
    assert done.returncode == 0, done.stderr
    return ws.write(f"robot_{use_pid}.urdf", done.stdout)


def convert(ws, *args: str):
    return ws.run(*TOOL, *args, timeout=120)


def _key(model: mujoco.MjModel, kind: str, index: int) -> tuple:
    if kind == "geom":
        return (model.geom_bodyid[index], model.geom_type[index],
                *np.round(model.geom_size[index], 6), *np.round(model.geom_pos[index], 6),
                model.geom_group[index])
    return (getattr(model, kind)(index).name,)


FIELDS = {"body": ("nbody", ("pos", "quat", "mass", "inertia", "gravcomp")),
          "jnt": ("njnt", ("type", "range", "pos", "axis")),
          "site": ("nsite", ("pos", "quat", "bodyid")),
          "cam": ("ncam", ("pos", "quat", "fovy", "resolution", "bodyid")),
          "sensor": ("nsensor", ("type", "objid")),
          "actuator": ("nu", ("trnid", "gainprm", "biasprm")),
          "geom": ("ngeom", ("type", "size", "pos", "quat", "bodyid", "group"))}


def differences(ours: Path, theirs: Path) -> list[str]:
    """Where two MJCF files compile to different models (element order aside; a
    quaternion and its negative are one rotation)."""
    a, b = mujoco.MjModel.from_xml_path(str(ours)), mujoco.MjModel.from_xml_path(str(theirs))
    found = []
    for kind, (count, fields) in FIELDS.items():
        if getattr(a, count) != getattr(b, count):
            found.append(f"{kind}: {getattr(a, count)} != {getattr(b, count)}")
            continue
        order_a = sorted(range(getattr(a, count)), key=lambda i: _key(a, kind, i))
        order_b = sorted(range(getattr(b, count)), key=lambda i: _key(b, kind, i))
        if kind != "geom" and [_key(a, kind, i) for i in order_a] != \
                [_key(b, kind, i) for i in order_b]:
            found.append(f"{kind}: names differ")
            continue
        for field in fields:
            x = getattr(a, f"{kind}_{field}")[order_a]
            y = getattr(b, f"{kind}_{field}")[order_b]
            same = np.allclose(np.abs((x * y).sum(axis=1)), 1, atol=1e-5) \
                if field == "quat" else np.allclose(x, y, atol=1e-5)
            if not same:
                found.append(f"{kind}_{field}")
    for field in ("dof_damping", "dof_frictionloss", "eq_type", "eq_data"):
        if getattr(a, field).shape != getattr(b, field).shape or \
                not np.allclose(getattr(a, field), getattr(b, field)):
            found.append(field)
    if a.opt.integrator != b.opt.integrator:
        found.append("integrator")
    return found


def test_the_demo_inputs_files_make_the_model_the_converter_makes(demo_ws):
    urdf = expanded(demo_ws, "false")
    done = convert(demo_ws, "-u", str(urdf),
                   "-m", str(resources() / "mjcf_generation" / "test_inputs.xml"),
                   "--scene", str(resources() / "scenes" / "scene_info.xml"),
                   "--save_only", "-o", "out")
    assert done.returncode == 0, done.stderr
    made = demo_ws.root / "out" / "mujoco_description_formatted.xml"
    assert differences(made, RECORDED / "files_mujoco_description_formatted.xml") == []
    assert (demo_ws.root / "out" / "scene_info.xml").is_file()  # --scene copied beside it


def test_inputs_inside_the_urdf_make_the_model_and_scene_the_converter_makes(demo_ws,
                                                                              tmp_path):
    urdf = expanded(demo_ws, "true")
    done = convert(demo_ws, "-u", str(urdf), "--save_only", "-o", "out")
    assert done.returncode == 0, done.stderr
    out = demo_ws.root / "out"
    assert differences(out / "mujoco_description_formatted.xml",
                       RECORDED / "urdf_mujoco_description_formatted.xml") == []
    theirs = tmp_path / "theirs"
    theirs.mkdir()
    shutil.copy(RECORDED / "urdf_mujoco_description_formatted.xml",
                theirs / "mujoco_description_formatted.xml")
    shutil.copy(RECORDED / "urdf_scene.xml", theirs / "scene.xml")
    assert differences(out / "scene.xml", theirs / "scene.xml") == []  # with its scene


def test_the_camera_sits_on_its_link_looking_down_the_optical_axis(demo_ws):
    urdf = expanded(demo_ws, "true")
    assert convert(demo_ws, "-u", str(urdf), "--save_only", "-o", "out").returncode == 0
    model = mujoco.MjModel.from_xml_path(str(demo_ws.root / "out" / "scene.xml"))
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    camera, site = model.camera("camera").id, model.site("camera_color_optical_frame").id
    assert np.allclose(data.cam_xpos[camera], data.site_xpos[site])
    optical_z = data.site_xmat[site].reshape(3, 3)[:, 2]
    looks = -data.cam_xmat[camera].reshape(3, 3)[:, 2]  # a MuJoCo camera looks down -z
    assert np.allclose(looks, optical_z, atol=1e-5)
    ranges = [model.sensor(i).name for i in range(model.nsensor)
              if model.sensor_type[i] == mujoco.mjtSensor.mjSENS_RANGEFINDER]
    assert len(ranges) == 24 and ranges[0] == "lidar-00"  # one per 0.025 rad over 0.6 rad


def binary_stl(points: list[tuple], faces: list[tuple]) -> bytes:
    out = bytearray(b"\0" * 80) + struct.pack("<I", len(faces))
    for face in faces:
        out += struct.pack("<3f", 0, 0, 0)
        for index in face:
            out += struct.pack("<3f", *points[index])
        out += b"\0\0"
    return bytes(out)


DEFAULT_CLASSES = """<default>
  <default class="visual"><geom group="2" type="mesh" contype="0" conaffinity="0"/></default>
  <default class="collision"><geom group="3" type="mesh"/></default>
</default>"""


def test_stl_meshes_through_package_uris_are_gathered_into_assets(demo_ws):
    mesh = demo_ws.root / "meshes_pkg" / "meshes" / "part.stl"
    mesh.parent.mkdir(parents=True)
    mesh.write_bytes(binary_stl([(0, 0, 0), (0.1, 0, 0), (0, 0.1, 0), (0, 0, 0.1)],
                                [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]))
    demo_ws.write("meshes_pkg/package.xml", """
        <package format="3"><name>meshes_pkg</name><version>0.0.0</version>
        <description>d</description><maintainer email="a@b.c">a</maintainer>
        <license>MIT</license></package>
        """)
    demo_ws.env["LAUNCHER_PACKAGE_PATH"] += f":{mesh.parent.parent}"
    urdf = demo_ws.write("meshy.urdf", """
        <robot name="meshy">
          <link name="base"/>
          <link name="arm">
            <inertial><mass value="1"/>
              <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
            <visual><geometry><mesh filename="package://meshes_pkg/meshes/part.stl"/>
            </geometry><material name="m"><color rgba="0 1 0 1"/></material></visual>
          </link>
          <joint name="j" type="revolute"><parent link="base"/><child link="arm"/>
            <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
        </robot>
        """)
    inputs = demo_ws.write("inputs.xml", f"<mujoco_inputs><raw_inputs>{DEFAULT_CLASSES}"
                                         "</raw_inputs></mujoco_inputs>")
    done = convert(demo_ws, "-u", str(urdf), "-m", str(inputs), "--save_only", "-o", "out")
    assert done.returncode == 0, done.stderr
    out = demo_ws.root / "out"
    assert (out / "assets" / "full" / "part.stl").read_bytes() == mesh.read_bytes()
    model = mujoco.MjModel.from_xml_path(str(out / "mujoco_description_formatted.xml"))
    meshes = [i for i in range(model.ngeom) if model.geom_type[i] == mujoco.mjtGeom.mjGEOM_MESH]
    assert sorted(model.geom_group[i] for i in meshes) == [2, 3]  # a visual and a collision
    assert any(np.allclose(model.geom_rgba[i], [0, 1, 0, 1]) for i in meshes)


def test_find_missing_inertias_passes_the_demo_robot(demo_ws):
    done = demo_ws.run("run", "mujoco_ros2_control", "find_missing_inertias.py",
                       str(expanded(demo_ws, "false")))
    assert done.returncode == 0, done.stderr
    assert "All moving joints have at least one static descendant" in done.stdout


def test_find_missing_inertias_names_each_joint_and_its_links(demo_ws):
    urdf = demo_ws.write("bad.urdf", """
        <robot name="bad">
          <link name="base"/>
          <link name="arm"/>
          <link name="tool"/>
          <joint name="shoulder" type="revolute"><parent link="base"/><child link="arm"/>
            <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
          <joint name="flange" type="fixed"><parent link="arm"/><child link="tool"/></joint>
        </robot>
        """)
    done = demo_ws.run("run", "mujoco_ros2_control", "find_missing_inertias.py", str(urdf))
    assert done.returncode == 1
    assert f"Invalid joint: shoulder ({urdf}:5)" in done.stdout
    assert "arm, tool" in done.stdout


# Bad inputs: each a clear error, at its place, nothing left behind.

def _inputs(ws, body: str) -> Path:
    return ws.write("inputs.xml", f"<mujoco_inputs>\n  <processed_inputs>\n{body}\n"
                                  "  </processed_inputs>\n</mujoco_inputs>\n")


def _refused(ws, inputs: Path, use_pid: str = "false") -> str:
    done = convert(ws, "-u", str(expanded(ws, use_pid)), "-m", str(inputs), "-s", "-o", "o")
    assert done.returncode == 1, done.stdout
    assert "Traceback" not in done.stderr
    return done.stderr


def test_an_unknown_processed_input_is_refused_at_its_line_with_the_nearest(demo_ws):
    err = _refused(demo_ws, _inputs(demo_ws, '    <camra site="camera_link" name="c"/>'))
    assert "inputs.xml:3:5" in err and "<camra> is not a processed input" in err, err
    assert "did you mean 'camera'" in err, err


def test_a_camera_at_a_link_the_robot_lacks_is_refused_with_the_nearest(demo_ws):
    err = _refused(demo_ws, _inputs(demo_ws, '    <camera site="camera_lnk" name="cam"/>'))
    assert "camera 'cam' site: 'camera_lnk' is not a link of the robot" in err, err
    assert "did you mean 'camera_link'" in err, err


def test_a_lidar_without_an_angle_step_is_refused_at_its_line(demo_ws):
    err = _refused(demo_ws, _inputs(demo_ws, '    <lidar ref_site="lidar_sensor_frame" '
                                    'sensor_name="rf" min_angle="0" max_angle="1" '
                                    'angle_increment="0"/>'))
    assert "inputs.xml:3:5" in err and "angle_increment is 0; it must be greater than zero" \
        in err, err


def test_a_modify_element_without_a_name_is_refused_at_its_line(demo_ws):
    err = _refused(demo_ws, _inputs(demo_ws, '    <modify_element type="joint" damping="1"/>'))
    assert "inputs.xml:3:5" in err and 'type="joint"> needs name=' in err, err


def test_raw_inputs_mujoco_refuses_are_said_with_the_made_file(demo_ws):
    inputs = demo_ws.write("inputs.xml", f"<mujoco_inputs><raw_inputs>{DEFAULT_CLASSES}"
                                         '<actuator><position name="a" joint="no_such_joint"/>'
                                         "</actuator></raw_inputs></mujoco_inputs>")
    err = _refused(demo_ws, inputs)
    assert "mujoco_description_formatted.xml: the MJCF made of" in err, err
    assert "no_such_joint" in err, err


def test_inputs_without_the_visual_and_collision_classes_are_told_to_define_them(demo_ws):
    err = _refused(demo_ws, demo_ws.write("inputs.xml", "<mujoco_inputs/>"))
    assert "unknown default class name 'collision'" in err, err
    assert "define both in <raw_inputs><default>" in err, err


def test_a_urdf_mujoco_cannot_compile_points_to_find_missing_inertias(demo_ws):
    urdf = demo_ws.write("bad.urdf", """
        <robot name="bad">
          <link name="base"/>
          <link name="arm"><visual><geometry><box size="1 1 1"/></geometry></visual></link>
          <joint name="shoulder" type="revolute"><parent link="base"/><child link="arm"/>
            <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
        </robot>
        """)
    done = convert(demo_ws, "-u", str(urdf), "-s", "-o", "o")
    assert done.returncode == 1
    assert "MuJoCo cannot compile the URDF" in done.stderr, done.stderr
    assert "find_missing_inertias.py" in done.stderr, done.stderr


def test_neither_publishing_nor_saving_is_refused(demo_ws):
    done = convert(demo_ws, "-u", str(expanded(demo_ws, "false")))
    assert done.returncode == 1
    assert "give --publish_topic TOPIC" in done.stderr, done.stderr


def test_a_modify_element_that_matches_nothing_is_a_warning(demo_ws):
    inputs = demo_ws.write("inputs.xml", f"<mujoco_inputs><raw_inputs>{DEFAULT_CLASSES}"
                                         "</raw_inputs><processed_inputs>"
                                         '<modify_element type="joint" name="joint9" damping="1"/>'
                                         "</processed_inputs></mujoco_inputs>")
    done = convert(demo_ws, "-u", str(expanded(demo_ws, "false")), "-m", str(inputs), "-s",
                   "-o", "o")
    assert done.returncode == 0, done.stderr
    assert "warning: modify_element: no joint named 'joint9' in the MJCF" in done.stderr


def one_mesh_arm(ws, name: str, mesh: str) -> Path:
    """A URDF arm whose one moving link's only visual is `mesh`."""
    return ws.write(f"{name}.urdf", f"""
        <robot name="{name}">
          <link name="base"/>
          <link name="arm">
            <inertial><mass value="1"/>
              <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
            <visual><geometry><mesh filename="{mesh}"/></geometry></visual>
          </link>
          <joint name="j" type="revolute"><parent link="base"/><child link="arm"/>
            <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
        </robot>
        """)


COLLADA_TETRAHEDRON = """<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Y_UP</up_axis></asset>
  <library_geometries><geometry id="m" name="part"><mesh>
    <source id="p"><float_array id="pa" count="12">0 0 0 0.1 0 0 0 0.1 0 0 0 0.1</float_array>
      <technique_common><accessor source="#pa" count="4" stride="3"><param name="X"
        type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
      </accessor></technique_common></source>
    <vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
    <triangles count="4"><input semantic="VERTEX" source="#v" offset="0"/>
      <p>0 2 1 0 1 3 0 3 2 1 2 3</p></triangles>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="s"><node id="n"><instance_geometry url="#m"/>
  </node></visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
"""


def test_collada_meshes_become_obj_through_trimesh_installed_apart(demo_ws):
    """Real pip, real trimesh: installed into $ROS_HOME/ros2_control/.venv, as the
    converter's script installs its tools."""
    demo_ws.env["ROS_HOME"] = str(demo_ws.root / "ros_home")
    demo_ws.write("part.dae", COLLADA_TETRAHEDRON)
    urdf = one_mesh_arm(demo_ws, "dae", "part.dae")
    inputs = demo_ws.write("inputs.xml", f"<mujoco_inputs><raw_inputs>{DEFAULT_CLASSES}"
                                         "</raw_inputs></mujoco_inputs>")
    done = convert(demo_ws, "-u", str(urdf), "-m", str(inputs), "-s", "-o", "out")
    assert done.returncode == 0, done.stderr
    venv = demo_ws.root / "ros_home" / "ros2_control" / ".venv"
    assert f"numpy into {venv} (once; later runs reuse it)" in done.stdout, done.stdout
    out = demo_ws.root / "out"
    assert (out / "assets" / "full" / "part.obj").is_file()
    model = mujoco.MjModel.from_xml_path(str(out / "mujoco_description_formatted.xml"))
    corners = model.mesh_vert[model.mesh_vertadr[0]:][:model.mesh_vertnum[0]]
    edges = sorted(np.linalg.norm(a - b) for i, a in enumerate(corners) for b in corners[i + 1:])
    assert np.allclose(edges, [0.1] * 3 + [0.1 * 2 ** 0.5] * 3, atol=1e-6)  # the tetrahedron


def test_add_free_joint_floats_the_root_link(demo_ws):
    urdf = demo_ws.write("cart.urdf", """
        <robot name="cart">
          <link name="base_link">
            <inertial><mass value="2"/>
              <inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
            <visual><geometry><box size="0.4 0.3 0.1"/></geometry></visual>
          </link>
        </robot>
        """)
    inputs = demo_ws.write("inputs.xml", f"<mujoco_inputs><raw_inputs>{DEFAULT_CLASSES}"
                                         "</raw_inputs></mujoco_inputs>")
    done = convert(demo_ws, "-u", str(urdf), "-m", str(inputs), "-f", "-s", "-o", "out")
    assert done.returncode == 0, done.stderr
    model = mujoco.MjModel.from_xml_path(
        str(demo_ws.root / "out" / "mujoco_description_formatted.xml"))
    joint = model.joint("floating_base_joint")
    assert joint.type == mujoco.mjtJoint.mjJNT_FREE
    assert model.body(model.jnt_bodyid[joint.id]).name == "base_link"


def obj_vertices(path: Path) -> list[tuple[float, ...]]:
    return sorted({tuple(round(float(v), 4) for v in line.split()[1:4])
                   for line in path.read_text().splitlines() if line.startswith("v ")})


def test_a_decomposed_mesh_collides_as_the_convex_parts_the_converter_cuts(demo_ws):
    """Real pip, real CoACD (installed apart, as for COLLADA), the parts compared with those
    mujoco_ros2_control's converter cut of the same mesh."""
    demo_ws.env["ROS_HOME"] = str(demo_ws.root / "ros_home")
    mesh = RECORDED / "decomposed" / "ell.stl"
    urdf = one_mesh_arm(demo_ws, "ell", str(mesh))
    inputs = demo_ws.write("inputs.xml", f"<mujoco_inputs><raw_inputs>{DEFAULT_CLASSES}"
                                         "</raw_inputs><processed_inputs><decompose_mesh "
                                         'mesh_name="ell" threshold="0.05"/></processed_inputs>'
                                         "</mujoco_inputs>")
    done = convert(demo_ws, "-u", str(urdf), "-m", str(inputs), "-c", "-s", "-o", "out")
    assert done.returncode == 0, done.stderr
    out = demo_ws.root / "out"
    ours = sorted(obj_vertices(p) for p in (out / "assets" / "decomposed" / "ell").glob("*.obj"))
    theirs = sorted(obj_vertices(p) for p in (RECORDED / "decomposed").glob("*.obj"))
    assert ours == theirs and len(ours) == 2
    model = mujoco.MjModel.from_xml_path(str(out / "mujoco_description_formatted.xml"))
    collides = sorted(model.mesh(model.geom_dataid[g]).name for g in range(model.ngeom)
                      if model.geom_group[g] == 3)
    assert collides == ["ell_collision_0", "ell_collision_1"]  # the visual stays whole
