"""SDF worlds and models into MuJoCo: real MjSpec and MuJoCo, files written inline, the
bus replaced by the recording stand-in of test_sim."""

from __future__ import annotations

import math
import re
from pathlib import Path
from types import SimpleNamespace

import mujoco
import numpy as np
import pytest

from launcher.errors import LaunchError
from launcher.sim import sdf
from launcher.sim.loading import load_world_file
from launcher.sim.resources import model_file
from launcher.sim.templates import Templates
from launcher.sim.world import World
from tests.support.environment import REPO, shared
from tests.support.robots import CLASSIC_ROBOT, WHEEL
from tests.support.sim import Recorder

WORLDS = ("external", "gz-sim", "worlds")  # gz-sim's, in ../shared
LIDAR = REPO / "packages" / "robot_description" / "meshes" / "lidar.stl"


def world_text(body: str, version: str = "1.9", name: str = "w") -> str:
    return f'<?xml version="1.0"?>\n<sdf version="{version}">\n<world name="{name}">\n{body}\n' \
           "</world>\n</sdf>\n"


def box_model(name: str, pose: str = "0 0 0.5 0 0 0", extra: str = "", static: bool = False,
              link: str = "link") -> str:
    return f"""<model name="{name}"><static>{str(static).lower()}</static><pose>{pose}</pose>
      <link name="{link}"><inertial><mass>1</mass><inertia><ixx>0.1</ixx><iyy>0.1</iyy>
      <izz>0.1</izz></inertia></inertial>
      <collision name="c"><geometry><box><size>1 1 1</size></box></geometry></collision>
      <visual name="v"><geometry><box><size>1 1 1</size></box></geometry></visual></link>
      {extra}</model>"""


def load(tmp_path: Path, text: str, name: str = "w.sdf", env: dict | None = None):
    path = tmp_path / name
    path.write_text(text)
    return sdf.load_world(text, path, env or {})


def make_world(tmp_path: Path, text: str, env: dict | None = None) -> tuple[World, Recorder]:
    path = tmp_path / "world.sdf"
    path.write_text(text)
    recorder = Recorder()
    return World.from_path(path, recorder, environ=env or {}), recorder


def run(world: World, steps: int) -> None:
    """Step as the server does: batches up to the next plugin update."""
    while steps > 0:
        batch = world.physics.steps_until_update(steps)
        world.physics.step(batch)
        steps -= batch


def error_of(tmp_path: Path, text: str, env: dict | None = None) -> str:
    with pytest.raises(LaunchError) as caught:
        load(tmp_path, text, env=env)
    return str(caught.value)


# --- gz-sim's own worlds, unchanged -------------------------------------------------------
@pytest.mark.parametrize("name", ["empty", "shapes", "diff_drive"])
def test_gz_sims_worlds_load(name):
    path = shared(*WORLDS, f"{name}.sdf")
    loaded = sdf.load_world(path.read_text(), path)
    model = loaded.spec.compile()
    assert loaded.name == name and model.nbody > 1
    assert "ground_plane" in [m.name for m in loaded.models]
    assert model.opt.timestep == pytest.approx(0.001)


def test_shapes_are_the_sizes_gazebo_draws(tmp_path):
    loaded = load_world_file(shared(*WORLDS, "shapes.sdf"))
    model = loaded.spec.compile()
    geom = {model.geom(i).name: i for i in range(model.ngeom)}
    box = geom["box/box_link/collision/box_collision"]
    assert model.geom_type[box] == mujoco.mjtGeom.mjGEOM_BOX
    assert model.geom_size[box] == pytest.approx([0.5, 0.5, 0.5])
    cylinder = geom["cylinder/cylinder_link/collision/cylinder_collision"]
    assert model.geom_size[cylinder][:2] == pytest.approx([0.5, 0.5])  # radius, half length
    capsule = geom["capsule/capsule_link/collision/capsule_collision"]
    assert model.geom_size[capsule][:2] == pytest.approx([0.2, 0.3])
    ellipsoid = geom["ellipsoid/ellipsoid_link/collision/ellipsoid_collision"]
    assert model.geom_size[ellipsoid] == pytest.approx([0.2, 0.3, 0.5])
    cone = geom["cone/cone_link/collision/cone_collision"]
    assert model.geom_type[cone] == mujoco.mjtGeom.mjGEOM_MESH
    visual = geom["box/box_link/visual/box_visual"]
    assert model.geom_rgba[visual] == pytest.approx([1, 0, 0, 1])  # <material><diffuse>
    assert model.geom_contype[visual] == 0 and model.geom_conaffinity[visual] == 0
    assert model.body_mass[model.body("box/box_link").id] == pytest.approx(1.0)
    assert model.body_mass[model.body("cone/cone_link").id] > 0  # <inertial auto="true">


def test_the_diff_drive_world_drives_blue_and_leaves_green(tmp_path):
    loaded = load_world_file(shared(*WORLDS, "diff_drive.sdf"))
    recorder = Recorder()
    world = World(loaded.spec, loaded.label, recorder, loaded.plugins, models=loaded.models)
    assert list(world.entities) == ["ground_plane", "vehicle_blue", "vehicle_green"]
    recorder.callbacks["/model/vehicle_blue/cmd_vel"](
        SimpleNamespace(linear=SimpleNamespace(x=0.5), angular=SimpleNamespace(z=0.0)))
    run(world, 3000)  # one command, as `gz topic -p` sends: Gazebo's DiffDrive keeps it
    names, positions, _ = world.placement.poses()
    blue, green = positions[names.index("vehicle_blue")], positions[names.index("vehicle_green")]
    assert blue[0] > 1.0 and abs(blue[1] - 2.0) < 0.05
    assert abs(green[0]) < 0.01 and abs(green[1] + 2.0) < 0.01
    odometry = recorder.published["/model/vehicle_blue/odometry"][-1]
    assert odometry.pose.position.x > 0.5  # published at 1 Hz, as the world asks


# --- worlds --------------------------------------------------------------------------------
def test_physics_gravity_scene_and_lights(tmp_path):
    loaded = load(tmp_path, world_text("""
      <physics><max_step_size>0.002</max_step_size><real_time_factor>0.5</real_time_factor>
      </physics><gravity>0 0 -3.7</gravity>
      <scene><ambient>0.2 0.3 0.4 1</ambient><background>0.1 0.2 0.3 1</background></scene>
      <light type="directional" name="sun"><pose>0 0 10 0 0 0</pose>
        <diffuse>0.5 0.5 0.5 1</diffuse><direction>0 0 -1</direction></light>
      <light type="spot" name="lamp"><pose>1 2 3 0 0 0</pose><spot><outer_angle>0.5</outer_angle>
        </spot></light>"""))
    model = loaded.spec.compile()
    assert model.opt.timestep == pytest.approx(0.002) and loaded.real_time_factor == 0.5
    assert model.opt.integrator == mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    assert model.opt.gravity == pytest.approx([0, 0, -3.7])
    assert model.vis.headlight.ambient == pytest.approx([0.2, 0.3, 0.4])
    assert model.nlight == 2 and model.light_pos[1] == pytest.approx([1, 2, 3])
    assert model.light_cutoff[1] == pytest.approx(math.degrees(0.5))
    assert model.ntex == 1  # the background as a flat sky box


def test_poses_relative_to_frames_nested_models_and_joint_axes(tmp_path):
    loaded = load(tmp_path, world_text("""
      <model name="arm"><pose>1 0 0 0 0 0</pose>
        <frame name="mount"><pose>0 0 1 0 0 1.5707963</pose></frame>
        <link name="base"><pose relative_to="mount">0 0 0 0 0 0</pose></link>
        <link name="tip"><pose relative_to="base">1 0 0 0 0 0</pose></link>
        <joint name="hinge" type="revolute"><parent>base</parent><child>tip</child>
          <axis><xyz expressed_in="__model__">1 0 0</xyz>
            <limit><lower>-1</lower><upper>1</upper></limit>
            <dynamics><damping>0.3</damping><friction>0.1</friction></dynamics></axis></joint>
        <model name="inner"><pose>0 0 2 0 0 0</pose><link name="l"/></model>
        <joint name="fix" type="fixed"><parent>base</parent><child>inner::l</child></joint>
      </model>"""))
    model = loaded.spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    assert data.xpos[model.body("arm/base").id] == pytest.approx([1, 0, 1], abs=1e-6)
    assert data.xpos[model.body("arm/tip").id] == pytest.approx([1, 1, 1], abs=1e-6)
    assert data.xpos[model.body("arm/inner::l").id] == pytest.approx([1, 0, 2], abs=1e-6)
    hinge = model.joint("arm/hinge")
    axis_world = data.xaxis[hinge.id]
    assert axis_world == pytest.approx([1, 0, 0], abs=1e-6)  # expressed in the model frame
    assert model.jnt_range[hinge.id] == pytest.approx([-1, 1]) and model.jnt_limited[hinge.id]
    assert model.dof_damping[model.jnt_dofadr[hinge.id]] == pytest.approx(0.3)
    assert model.dof_frictionloss[model.jnt_dofadr[hinge.id]] == pytest.approx(0.1)


@pytest.mark.parametrize("version, expected", [("1.4", [1, 0, 0]), ("1.6", [0, 1, 0])])
def test_an_axis_is_in_the_model_frame_before_sdf_1_5_and_in_the_joint_frame_after(
        tmp_path, version, expected):
    loaded = load(tmp_path, world_text("""
      <model name="m"><link name="a"/><link name="b"><pose>0 0 0 0 0 1.5707963</pose></link>
        <joint name="j" type="revolute"><parent>a</parent><child>b</child>
          <axis><xyz>1 0 0</xyz></axis></joint></model>""", version))
    model = loaded.spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    assert data.xaxis[model.joint("m/j").id] == pytest.approx(expected, abs=1e-6)


def test_joint_types(tmp_path):
    links = "".join(f'<link name="{n}"/>' for n in "abcdefg")
    axes = "<axis><xyz>1 0 0</xyz></axis><axis2><xyz>0 1 0</xyz></axis2>"
    joints = "".join(f'<joint name="{n}" type="{t}"><parent>a</parent><child>{c}</child>'
                     f'{axes}</joint>' for n, t, c in [("rev", "revolute", "b"), ("con", "continuous", "c"),
                                     ("pri", "prismatic", "d"), ("bal", "ball", "e"),
                                     ("fix", "fixed", "f"), ("uni", "universal", "g")])
    model = load(tmp_path, world_text(f'<model name="m">{links}{joints}</model>')).spec.compile()
    kinds = {model.joint(i).name: model.jnt_type[i] for i in range(model.njnt)}
    J = mujoco.mjtJoint
    assert kinds["m/rev"] == J.mjJNT_HINGE and kinds["m/con"] == J.mjJNT_HINGE
    assert kinds["m/pri"] == J.mjJNT_SLIDE and kinds["m/bal"] == J.mjJNT_BALL
    assert kinds["m/uni"] == J.mjJNT_HINGE and kinds["m/uni::axis2"] == J.mjJNT_HINGE
    assert "m/fix" not in kinds
    assert model.body_jntnum[model.body("m/f").id] == 0  # welded to its parent


def test_joint_limits_are_radians_in_a_spawned_model_as_in_a_world(tmp_path):
    # SDF's <limit> is in radians (sdformat.org/spec, joint.axis.limit); MuJoCo's compiler
    # reads angles as degrees unless told, and a spawned model is compiled apart from a world
    joint = ('<link name="a"/><link name="b"/><joint name="j" type="revolute"><parent>a'
             '</parent><child>b</child><axis><xyz>0 0 1</xyz><limit><lower>-3</lower>'
             '<upper>3</upper></limit></axis></joint>')
    world, _ = make_world(tmp_path, world_text(f'<model name="m">{joint}</model>'))
    template = world.templates.from_string(f'<sdf version="1.9"><model name="n">{joint}'
                                           '</model></sdf>', "n")
    world.spawn(template, "n", [0, 0, 1], [1, 0, 0, 0])
    for name in ("m/j", "n/j"):
        assert world.model.jnt_range[world.model.joint(name).id] == pytest.approx([-3, 3])


def test_inertia_is_turned_into_the_link_frame(tmp_path):
    model = load(tmp_path, world_text("""
      <model name="m"><link name="l"><inertial><pose>0.1 0 0 0 0 1.5707963</pose>
        <mass>2</mass><inertia><ixx>1</ixx><iyy>2</iyy><izz>3</izz></inertia></inertial>
      </link></model>""")).spec.compile()  # a thin plate: 1 + 2 = 3, on the bound
    body = model.body("m/l").id
    assert model.body_mass[body] == pytest.approx(2)
    assert model.body_ipos[body] == pytest.approx([0.1, 0, 0])
    assert sorted(model.body_inertia[body]) == pytest.approx([1, 2, 3], rel=1e-6)


def test_static_models_have_no_joint_and_others_a_free_one(tmp_path):
    model = load(tmp_path, world_text(box_model("s", static=True) + box_model("d", "3 0 1 0 0 0")
                                      )).spec.compile()
    assert model.body_jntnum[model.body("s/link").id] == 0
    free = model.body_jntadr[model.body("d/link").id]
    assert model.jnt_type[free] == mujoco.mjtJoint.mjJNT_FREE


def test_friction_colours_and_meshes(tmp_path):
    (tmp_path / "meshes").mkdir()
    (tmp_path / "meshes" / "lidar.stl").write_bytes(LIDAR.read_bytes())
    model = load(tmp_path, world_text("""
      <model name="m"><link name="l">
        <collision name="c"><geometry><sphere><radius>0.2</radius></sphere></geometry>
          <surface><friction><ode><mu>0.3</mu></ode></friction></surface></collision>
        <visual name="v"><geometry><mesh><uri>meshes/lidar.stl</uri><scale>2 2 2</scale></mesh>
          </geometry><material><script><name>Gazebo/Green</name></script></material></visual>
      </link></model>""")).spec.compile()
    assert model.geom_friction[model.geom("m/l/collision/c").id][0] == pytest.approx(0.3)
    visual = model.geom("m/l/visual/v").id
    assert model.geom_type[visual] == mujoco.mjtGeom.mjGEOM_MESH
    assert model.geom_rgba[visual] == pytest.approx([0, 1, 0, 1])


def test_a_contact_takes_the_lower_friction_of_the_two_as_in_gazebo(tmp_path):
    """Gazebo's engines combine two surfaces' mu as the lower one; MuJoCo takes the larger
    unless a geom has priority: a caster of mu 0 must slide on a ground of mu 1."""
    model = load(tmp_path, world_text("""
      <model name="ground"><static>true</static><link name="l"><collision name="c"><geometry>
        <plane><normal>0 0 1</normal><size>10 10</size></plane></geometry></collision></link>
      </model>
      <model name="caster"><pose>0 0 0.1 0 0 0</pose><link name="l"><inertial><mass>1</mass>
        </inertial><collision name="c"><geometry><sphere><radius>0.1</radius></sphere>
        </geometry><surface><friction><ode><mu>0</mu></ode></friction></surface></collision>
      </link></model>
      <model name="tyre"><pose>2 0 0.1 0 0 0</pose><link name="l"><inertial><mass>1</mass>
        </inertial><collision name="c"><geometry><sphere><radius>0.1</radius></sphere>
        </geometry><surface><friction><ode><mu>2</mu></ode></friction></surface></collision>
      </link></model>""")).spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    touching = {tuple(sorted((model.geom(int(c.geom[0])).name, model.geom(int(c.geom[1])).name))):
                float(c.friction[0]) for c in data.contact[:data.ncon]}
    assert touching[("caster/l/collision/c", "ground/l/collision/c")] == \
        pytest.approx(0.0, abs=1e-4)  # (MuJoCo keeps a floor of 1e-5)
    assert touching[("ground/l/collision/c", "tyre/l/collision/c")] == 1.0  # min(2, 1)


def test_includes_by_model_uri_with_name_pose_and_plugins(tmp_path):
    folder = tmp_path / "models" / "crate"
    folder.mkdir(parents=True)
    (folder / "model.config").write_text(
        '<model><sdf version="1.5">old.sdf</sdf><sdf version="1.9">model.sdf</sdf>'
        '<sdf version="2.0">future.sdf</sdf></model>')
    (folder / "model.sdf").write_text(f'<sdf version="1.9">{box_model("crate")}</sdf>')
    assert model_file(folder).name == "model.sdf"  # the highest version launcher reads
    env = {"GZ_SIM_RESOURCE_PATH": str(tmp_path / "models")}
    loaded = load(tmp_path, world_text("""
      <include><uri>model://crate</uri></include>
      <include><uri>model://crate</uri><name>second</name><pose>4 0 1 0 0 0</pose>
        <plugin filename="gz-sim-joint-state-publisher-system"
                name="gz::sim::systems::JointStatePublisher"/></include>
      <include><uri>models/crate</uri><name>third</name></include>
      <model name="shelf"><pose>0 5 0 0 0 0</pose><static>true</static><link name="board"/>
        <include><uri>model://crate</uri><name>on_it</name></include></model>"""), env=env)
    assert [m.name for m in loaded.models] == ["crate", "second", "third", "shelf"]
    assert loaded.models[1].plugins[0].filename == "gz-sim-joint-state-publisher-system"
    model = loaded.spec.compile()
    assert model.body_pos[model.body("second/link").id] == pytest.approx([4, 0, 1])
    assert model.body_pos[model.body("crate/link").id] == pytest.approx([0, 0, 0.5])
    nested = model.body("shelf/on_it::link").id  # placed by the included model's own pose
    assert model.body_pos[nested] == pytest.approx([0, 5, 0.5])


def test_the_courses_box_model_spawns_from_model_config(tmp_path):
    models = REPO / "packages" / "robot_gazebo" / "models"
    descriptions = Templates(environ={"GZ_SIM_RESOURCE_PATH": str(models)})
    template = descriptions.from_file("model://box_model")
    assert template.name == "box_model" and template.pose.pos == (0, 0, 0.5)
    recorder = Recorder()
    loaded = load_world_file(REPO / "launcher" / "builtin" / "mujoco_sim" / "worlds" /
                             "empty.sdf")
    world = World(loaded.spec, loaded.label, recorder, loaded.plugins, descriptions,
                  models=loaded.models)
    world.spawn(template, "second_model", [6, 0, 0.5], [1, 0, 0, 0])
    text = f'<sdf version="1.6">{box_model("inline")}</sdf>'
    world.spawn(descriptions.from_string(text), "", [0, 3, 0.5], [1, 0, 0, 0])
    assert list(world.entities) == ["ground_plane", "second_model", "inline"]
    run(world, 500)
    names, positions, _ = world.placement.poses()
    assert positions[names.index("second_model")] == pytest.approx([6, 0, 0.5], abs=0.01)


# --- world models are entities -------------------------------------------------------------
def test_the_tests_stand_in_is_a_transport_and_from_path_logs_what_is_left_out(tmp_path):
    from launcher.sim.transport import Transport

    assert isinstance(Recorder(), Transport)
    world, recorder = make_world(tmp_path, world_text(
        box_model("cube") + '<actor name="walker"/>' +
        "<physics><real_time_factor>2</real_time_factor></physics>"))
    assert world.real_time_factor == 2.0
    assert any("<actor> in <world> is ignored" in m for m in recorder.messages("warning"))


def test_world_models_are_listed_moved_removed_and_reset(tmp_path):
    world, recorder = make_world(tmp_path, world_text(
        box_model("table", "1 1 0.5 0 0 0", static=True) +
        box_model("cube", "0 0 0.5 0 0 0", link="body")))
    assert list(world.entities) == ["table", "cube"]
    world.placement.set_pose("table", [5, 5, 0.5], [1, 0, 0, 0])  # a static model moves too
    world.placement.set_pose("cube", [0, -3, 2], [1, 0, 0, 0])
    names, positions, _ = world.placement.poses()
    assert positions[0] == pytest.approx([5, 5, 0.5])
    assert positions[1] == pytest.approx([0, -3, 2])
    world.reset()
    _, positions, _ = world.placement.poses()
    assert positions[0] == pytest.approx([1, 1, 0.5]) and positions[1] == pytest.approx([0, 0, 0.5])
    world.remove("table")
    assert list(world.entities) == ["cube"]
    assert world.model.nbody == 2


def test_a_models_pose_is_its_frame_not_its_link(tmp_path):
    world, _ = make_world(tmp_path, world_text("""<model name="car"><pose>1 2 0 0 0 0</pose>
        <link name="chassis"><pose>-0.5 0 0.3 0 0 0</pose></link></model>"""))
    assert world.placement.poses()[1][0] == pytest.approx([1, 2, 0])
    world.placement.set_pose("car", [3, 3, 1], [1, 0, 0, 0])
    assert world.data.xpos[world.model.body("car/chassis").id] == pytest.approx([2.5, 3, 1.3])


def test_mjcf_worlds_top_level_bodies_are_entities(tmp_path):
    from launcher.sim import mjcf

    source = mjcf.read("""<mujoco model="m"><worldbody><geom type="plane" size="5 5 1"/>
      <body name="crate" pos="1 0 0.2"><freejoint/><geom type="box" size=".2 .2 .2"/></body>
      <body name="shelf" pos="0 2 0.5"><geom type="box" size=".5 .2 .5"/></body>
      </worldbody></mujoco>""", None)
    world = World(mjcf.compile_spec(source), "m.xml", Recorder())
    assert list(world.entities) == ["crate", "shelf"]
    world.placement.set_pose("shelf", [0, 4, 0.5], [1, 0, 0, 0])
    world.placement.set_pose("crate", [2, 0, 0.2], [1, 0, 0, 0])
    assert world.placement.poses()[1] == pytest.approx(np.array([[2, 0, 0.2], [0, 4, 0.5]]))


def test_the_mjcf_lidar_extension_becomes_one_plugin_per_sensor_lines_kept():
    from launcher.sim import mjcf

    text = """<mujoco model="m">
  <extension>
    <plugin plugin="mujoco.plugin.lidar">
      <instance name="flat"><config key="resolution" value="5 1"/>
        <config key="max_range" value="9"/></instance>
    </plugin>
  </extension>
  <worldbody><site name="s"/></worldbody>
  <sensor>
    <plugin name="front" instance="flat" objtype="site" objname="s">
      <config key="max_range" value="4"/></plugin>
  </sensor>
</mujoco>"""
    source = mjcf.read(text, None)
    assert source.text.count("\n") == text.count("\n")  # MuJoCo's lines still point home
    assert "lidar" not in source.text
    (lidar,) = source.plugins
    assert (lidar.filename, lidar.name, lidar.where) == ("mujoco.plugin.lidar", "front",
                                                         "<string>:10")
    configs = {c.get("key"): c.get("value") for c in lidar.element.findall("config")}
    assert configs == {"resolution": "5 1", "max_range": "4"}  # the sensor's own win
    assert lidar.element.get("objname") == "s"


# --- plugins -------------------------------------------------------------------------------
def test_gazebo_system_spellings_infrastructure_and_cpp_plugins(tmp_path):
    world, recorder = make_world(tmp_path, world_text("""
      <plugin filename="ignition-gazebo-physics-system" name="ignition::gazebo::systems::Physics"/>
      <plugin filename="libgz-sim8-sensors-system.so" name="gz::sim::systems::Sensors"/>
      <plugin filename="libmy_gazebo_world_plugin.so" name="my_gazebo_world_plugin"/>
      <plugin filename="gz-sim-buoyancy-system" name="gz::sim::systems::Buoyancy"/>""" +
        box_model("bot", extra="""<joint name="w" type="revolute"><parent>link</parent>
          <child>wheel</child></joint><link name="wheel"><pose>0 0 0 0 0 0</pose></link>
          <plugin filename="libignition-gazebo-joint-state-publisher-system.so"
                  name="ignition::gazebo::systems::JointStatePublisher"/>""")))
    world.load_world_plugins()
    warnings = recorder.messages("warning")
    assert len(warnings) == 2 and not recorder.messages("error"), recorder.logged
    assert "libmy_gazebo_world_plugin.so' (name 'my_gazebo_world_plugin') is a C++ library" \
        in warnings[0] and "world.sdf:" in warnings[0]
    assert "gz-sim-buoyancy-system" in warnings[1] and "does not provide" in warnings[1]
    assert [type(p).__name__ for p in world.entities["bot"].plugins] == ["JointStatePublisher"]




@pytest.mark.parametrize("params, cmd_topic, odom_topic", [
    ("<leftJoint>left_wheel_joint</leftJoint><rightJoint>right_wheel_joint</rightJoint>"
     "<wheelSeparation>0.3</wheelSeparation><wheelDiameter>0.1</wheelDiameter>"
     "<commandTopic>cmd_vel</commandTopic><odometryTopic>odom</odometryTopic>"
     "<odometryFrame>odom</odometryFrame><robotBaseFrame>base_link</robotBaseFrame>"
     "<publishOdomTF>true</publishOdomTF><updateRate>50</updateRate>", "/cmd_vel", "/odom"),
    ("<ros><namespace>/demo</namespace><remapping>cmd_vel:=cmd_demo</remapping></ros>"
     "<left_joint>left_wheel_joint</left_joint><right_joint>right_wheel_joint</right_joint>"
     "<wheel_separation>0.3</wheel_separation><wheel_diameter>0.1</wheel_diameter>"
     "<publish_odom>true</publish_odom><odometry_frame>odom</odometry_frame>"
     "<robot_base_frame>base_link</robot_base_frame>", "/demo/cmd_demo", "/demo/odom"),
], ids=["ros1", "ros2"])
def test_classic_gazebo_ros_diff_drive_speaks_ros_types(params, cmd_topic, odom_topic):
    wheels = WHEEL.format(side="left", y=0.15) + WHEEL.format(side="right", y=-0.15)
    text = CLASSIC_ROBOT.format(wheels=wheels, params=params)
    loaded = load_world_file(REPO / "launcher" / "builtin" / "mujoco_sim" / "worlds" /
                             "empty.sdf")
    recorder = Recorder()
    world = World(loaded.spec, loaded.label, recorder, loaded.plugins, models=loaded.models)
    world.spawn(Templates().from_string(text), "bot", [0, 0, 0], [1, 0, 0, 0])
    for _ in range(20):
        recorder.callbacks[cmd_topic](SimpleNamespace(linear=SimpleNamespace(x=0.4),
                                                      angular=SimpleNamespace(z=0.0)))
        run(world, 100)
    odometry = recorder.published[odom_topic][-1]
    assert odometry.pose.pose.position.x > 0.5  # nav_msgs/Odometry's nesting
    assert not recorder.messages("warning"), recorder.logged  # every parameter known
    assert odometry.child_frame_id == "base_link" and odometry.header.frame_id == "odom"
    if "publishOdomTF" in params:
        assert recorder.published["/tf"][-1].transforms[0].child_frame_id == "base_link"


# --- bad input: where, what, what was expected --------------------------------------------
BAD_WORLDS = {
    "malformed XML": ('<sdf version="1.9"><world name="w">\n<model name="m"></world></sdf>',
                      "w.sdf:2:"),
    "unsupported version": ('<sdf version="2.0"><world name="w"/></sdf>',
                            "unsupported SDF version '2.0': launcher reads SDF 1.4 to 1.11"),
    "include not found": (world_text("<include><uri>model://nowhere</uri></include>"),
                          "model 'nowhere' (model://nowhere) not found; searched: "),
    "missing parent link": (world_text("""<model name="m"><link name="base"/>
        <joint name="j" type="revolute"><parent>bsae</parent><child>base</child></joint>
        </model>"""), "joint 'j': parent link 'bsae' does not exist in model 'm' "
                      "(did you mean 'base'?)"),
    "missing child link": (world_text("""<model name="m"><link name="a"/>
        <joint name="j" type="fixed"><parent>a</parent><child>b</child></joint></model>"""),
                           "child link 'b' does not exist"),
    "two models one name": (world_text(box_model("crate") + box_model("crate")),
                            "two models named 'crate' in world 'w' (the first at "),
    "zero mass": (world_text("""<model name="m"><link name="l"><inertial><mass>0</mass>
        </inertial></link></model>"""), "<mass> must be > 0 for a link that moves, got 0"),
    "negative mass": (world_text("""<model name="m"><link name="l"><inertial><mass>-2</mass>
        </inertial></link></model>"""), "got -2"),
    "non-positive-definite inertia": (world_text("""<model name="m"><link name="l"><inertial>
        <mass>1</mass><inertia><ixx>1</ixx><iyy>1</iyy><izz>5</izz></inertia></inertial>
        </link></model>"""), "is not positive definite"),
    "mesh not found": (world_text("""<model name="m"><link name="l"><visual name="v">
        <geometry><mesh><uri>meshes/gone.stl</uri></mesh></geometry></visual></link>
        </model>"""), "mesh 'meshes/gone.stl' not found: looked for "),
    "unknown relative_to frame": (world_text("""<model name="m"><link name="a"/>
        <link name="b"><pose relative_to="c">0 0 1 0 0 0</pose></link></model>"""),
                                  "unknown frame 'c' in model 'm'"),
    "unknown joint type": (world_text("""<model name="m"><link name="a"/><link name="b"/>
        <joint name="j" type="revolut"><parent>a</parent><child>b</child></joint></model>"""),
                           "unknown type 'revolut' (did you mean 'revolute'"),
    "a world file with no world": ('<sdf version="1.6"><model name="m"/></sdf>',
                                   "no <world> in this SDF file"),
}


@pytest.mark.parametrize("case", list(BAD_WORLDS))
def test_bad_sdf_is_one_clear_error_with_its_place(tmp_path, case):
    text, expected = BAD_WORLDS[case]
    message = error_of(tmp_path, text, env={"GZ_SIM_RESOURCE_PATH": str(tmp_path)})
    assert expected in message, message
    assert message.startswith(str(tmp_path / "w.sdf") + ":"), message  # file:line(:column)
    assert re.match(r".*w\.sdf:\d+", message)


def test_an_include_cycle_is_named(tmp_path):
    (tmp_path / "a").mkdir()
    (tmp_path / "a" / "model.sdf").write_text(
        '<sdf version="1.9"><model name="a"><link name="l"/>'
        "<include><uri>../b/model.sdf</uri></include></model></sdf>")
    (tmp_path / "b").mkdir()
    (tmp_path / "b" / "model.sdf").write_text(
        '<sdf version="1.9"><model name="b"><link name="l"/>'
        "<include><uri>../a/model.sdf</uri></include></model></sdf>")
    message = error_of(tmp_path, world_text("<include><uri>a/model.sdf</uri></include>"))
    assert "makes a cycle: " in message and "a/model.sdf -> " in message
    assert "b/model.sdf:1:" in message


def test_a_model_config_with_no_usable_sdf_says_what_it_offers(tmp_path):
    folder = tmp_path / "models" / "future"
    folder.mkdir(parents=True)
    (folder / "model.config").write_text('<model><sdf version="2.1">model.sdf</sdf></model>')
    message = error_of(tmp_path, world_text("<include><uri>model://future</uri></include>"),
                       env={"GZ_SIM_RESOURCE_PATH": str(tmp_path / "models")})
    assert "model.config: no <sdf> entry launcher can read: offered 2.1 (model.sdf)" in message
    (folder / "model.config").write_text("<model><name>future</name></model>")
    message = error_of(tmp_path, world_text("<include><uri>model://future</uri></include>"),
                       env={"GZ_SIM_RESOURCE_PATH": str(tmp_path / "models")})
    assert "no usable model file: expected <sdf version=" in message


def test_shapes_mujoco_cannot_express_are_one_warning_each_and_left_out(tmp_path):
    loaded = load(tmp_path, world_text("""<model name="land"><static>true</static>
      <link name="l">
        <collision name="hills"><geometry><heightmap><uri>h.png</uri></heightmap></geometry>
        </collision>
        <visual name="fence"><geometry><polyline><point>0 0</point><height>1</height>
        </polyline></geometry></visual>
        <visual name="box"><geometry><box><size>1 1 1</size></box></geometry></visual>
        <sensor name="cam" type="thermal_camera"/>
        <projector name="p"/>
        <wobble/>
      </link></model>
      <actor name="walker"/>"""))
    model = loaded.spec.compile()
    assert model.ngeom == 1  # only the box
    text = "\n".join(loaded.warnings)
    assert len(loaded.warnings) == 6, text
    assert re.search(r"w\.sdf:6: collision 'hills' is a heightmap, which MuJoCo cannot "
                     "express: it is left out", text), text
    assert "visual 'fence' is a polyline" in text
    assert "sensor 'cam' (type thermal_camera) is not simulated" in text
    assert "<wobble> in <link> is not known to launcher and is ignored" in text
    assert "<actor> in <world> is ignored: animated actors are not simulated" in text


def test_classic_joint_state_publisher_publishes_sensor_msgs_joint_states():
    wheels = WHEEL.format(side="left", y=0.15) + WHEEL.format(side="right", y=-0.15)
    text = CLASSIC_ROBOT.format(wheels=wheels, params="").replace(
        '<plugin filename="libgazebo_ros_diff_drive.so" name="diff_drive"></plugin>',
        '<plugin filename="libgazebo_ros_joint_state_publisher.so" name="joints">'
        "<robotNamespace>/bot</robotNamespace><jointName>left_wheel_joint</jointName>"
        "<updateRate>100</updateRate></plugin>")
    loaded = load_world_file(REPO / "launcher" / "builtin" / "mujoco_sim" / "worlds" /
                             "empty.sdf")
    recorder = Recorder()
    world = World(loaded.spec, loaded.label, recorder, loaded.plugins, models=loaded.models)
    world.spawn(Templates().from_string(text), "bot", [0, 0, 0], [1, 0, 0, 0])
    run(world, 50)
    states = recorder.published["/bot/joint_states"]
    assert states and states[-1].name == ["left_wheel_joint"]
    assert len(states) == pytest.approx(5, abs=1)  # 100 Hz for 50 ms


def test_worlds_and_models_are_found_on_every_gazebo_variable(tmp_path):
    from launcher.sim.resources import ResourceNotFound, find_model, find_world

    folders = {}
    for variable in ("GZ_SIM_RESOURCE_PATH", "IGN_GAZEBO_RESOURCE_PATH", "GAZEBO_MODEL_PATH",
                     "GAZEBO_RESOURCE_PATH", "MUJOCO_SIM_RESOURCE_PATH"):
        folders[variable] = tmp_path / variable.lower()
        folders[variable].mkdir()
    env = {variable: str(folder) for variable, folder in folders.items()}
    (folders["IGN_GAZEBO_RESOURCE_PATH"] / "old.world").write_text("<sdf/>")
    (folders["GAZEBO_RESOURCE_PATH"] / "worlds").mkdir()
    (folders["GAZEBO_RESOURCE_PATH"] / "worlds" / "classic.world").write_text("<sdf/>")
    (folders["GAZEBO_MODEL_PATH"] / "table").mkdir()
    assert find_world("old.world", env).parent == folders["IGN_GAZEBO_RESOURCE_PATH"]
    assert find_world("old", env).name == "old.world"  # a name, as `gz sim shapes` takes
    assert find_world("classic.world", env).name == "classic.world"  # <dir>/worlds, classic
    assert find_model("table", env) == folders["GAZEBO_MODEL_PATH"] / "table"
    with pytest.raises(ResourceNotFound) as caught:
        find_world("nowhere.sdf", env)
    message = str(caught.value)
    for variable, folder in folders.items():
        assert f"{folder} ({variable})" in message  # every folder searched, with its variable
        assert f"{variable}='{folder}'" in message  # and every variable's value
    with pytest.raises(ResourceNotFound) as caught:
        find_world("nowhere.sdf", {})
    assert "GZ_SIM_RESOURCE_PATH is not set" in str(caught.value)


def test_a_model_sdf_file_spawns_by_path_too():
    template = Templates().from_file(str(REPO / "packages" / "robot_gazebo" / "models" /
                                            "box_model" / "model.sdf"))
    assert template.name == "box_model" and template.root == "link" and not template.static


def test_a_create_without_a_pose_puts_an_sdf_model_at_its_own_pose():
    from launcher.sim.world_services import spawn_pose

    template = Templates(environ={"GZ_SIM_RESOURCE_PATH": str(
        REPO / "packages" / "robot_gazebo" / "models")}).from_file("model://box_model")

    def pose(x=0.0, w=0.0):
        return SimpleNamespace(position=SimpleNamespace(x=x, y=0.0, z=0.0),
                               orientation=SimpleNamespace(w=w, x=0.0, y=0.0, z=0.0))

    assert spawn_pose(pose(), template) == ([0, 0, 0.5], [1, 0, 0, 0])  # the model's <pose>
    assert spawn_pose(pose(w=1.0), template) == ([0, 0, 0.5], [1, 0, 0, 0])
    assert spawn_pose(pose(x=6.0), template) == ([6.0, 0, 0], [1, 0, 0, 0])  # as given


def test_a_systems_parameters_are_declared_a_typo_warns_and_a_bad_value_is_an_error(tmp_path):
    plugin = """<plugin filename="gz-sim-diff-drive-system" name="gz::sim::systems::DiffDrive">
        <left_joint>l</left_joint><right_joint>r</right_joint>{extra}</plugin>"""
    wheels = "".join(f"""<link name="{side}_wheel"/><joint name="{side}" type="revolute">
        <parent>link</parent><child>{side}_wheel</child></joint>""" for side in "lr")
    model = box_model("bot", extra=wheels + plugin)
    world, recorder = make_world(tmp_path, world_text(model.format(
        extra="<wheel_seperation>0.5</wheel_seperation>")))
    assert [type(p).__name__ for p in world.entities["bot"].plugins] == ["DiffDrive"]
    warning = next(m for m in recorder.messages("warning") if "wheel_seperation" in m)
    assert "world.sdf:" in warning and "did you mean 'wheel_separation'" in warning
    world, recorder = make_world(tmp_path, world_text(model.format(
        extra="<wheel_radius>-1</wheel_radius>")))
    error = next(m for m in recorder.messages("error") if "wheel_radius" in m)
    assert "plugin gz::sim::systems::DiffDrive: wheel_radius: expected a number > 0, got -1" \
        in error and "world.sdf:" in error
    assert world.entities["bot"].plugins == []  # the entity runs without it
    world, recorder = make_world(tmp_path, world_text(model.replace(
        "<right_joint>r</right_joint>", "<right_joint>l</right_joint>").format(extra="")))
    assert any("joint 'l' is given more than once" in m for m in recorder.messages("error"))


# --- custom elements, Gazebo's common models, the Fuel cache ------------------------------
def test_custom_elements_are_kept_and_ignored_and_an_undeclared_prefix_is_said(tmp_path):
    """libsdformat's rule: `<prefix:name>` elements are the user's own; Gazebo's worlds use
    `gz:` undeclared and `<gz::system_priority>` (which a namespace-aware XML parser
    refuses)."""
    text = world_text("""
    <plugin filename="gz-sim-forcetorque-system" name="gz::sim::systems::ForceTorque">
      <gz::system_priority>10</gz::system_priority>
    </plugin>
    <gz:policies><include_gui_default_plugins>true</include_gui_default_plugins></gz:policies>
    <mine:notes mine:author="me">a:b &lt;c:d&gt;</mine:notes>
    <theirs:notes/>""" + box_model("box", extra="<my:tag>1</my:tag>")).replace(
        '<sdf version="1.9">', '<sdf version="1.9" xmlns:mine="http://example.com/mine">')
    loaded = load(tmp_path, text)
    assert [m.name for m in loaded.models] == ["box"]
    warned = "\n".join(loaded.warnings)
    assert "w.sdf:10: custom element <theirs:notes>: its prefix 'theirs' is not declared" in \
        warned, warned
    assert "<my:tag>" in warned and "mine:" not in warned and "gz:" not in warned
    assert loaded.plugins[0].element.find("gz\u00b7\u00b7system_priority").text == "10"


def test_model_sun_and_ground_plane_are_built_in_when_no_copy_is_on_the_path(tmp_path):
    loaded = load(tmp_path, world_text("""
    <include><uri>model://ground_plane</uri></include>
    <include><uri>model://sun</uri><name>noon</name><pose>0 0 20 0 0 0</pose></include>"""))
    assert [m.name for m in loaded.models] == ["ground_plane"]
    model = loaded.spec.compile()
    light = model.light("noon")
    assert model.light_type[light.id] == mujoco.mjtLightType.mjLIGHT_DIRECTIONAL
    assert model.light_pos[light.id] == pytest.approx([0, 0, 20])


def fuel_cache(root: Path, versions: tuple[int, ...] = (1, 3)) -> Path:
    """A local Fuel cache as gz-fuel-tools keeps it, one model in some versions."""
    for version in versions:
        folder = root / "fuel.gazebosim.org" / "openrobotics" / "models" / "construction cone" \
            / str(version)
        folder.mkdir(parents=True)
        (folder / "model.config").write_text(
            '<model><name>cone</name><sdf version="1.6">model.sdf</sdf></model>')
        (folder / "model.sdf").write_text('<sdf version="1.6">' + box_model(
            f"cone_v{version}") + "</sdf>")
    return root


FUEL = "https://fuel.gazebosim.org/1.0/OpenRobotics/models/Construction Cone"


@pytest.mark.parametrize("uri, expected", [(FUEL, "cone_v3"), (f"{FUEL}/1", "cone_v1"),
                                           (f"{FUEL}/tip", "cone_v3")])
def test_a_fuel_url_is_found_in_the_local_fuel_cache(tmp_path, uri, expected):
    cache = fuel_cache(tmp_path / "cache")
    loaded = load(tmp_path, world_text(f"<include><uri>\n  {uri}\n  </uri></include>"),
                  env={"GZ_FUEL_CACHE_PATH": str(cache)})
    model = loaded.spec.compile()
    assert model.body(f"{expected}/link") is not None  # the cached model, under its own name
    assert [m.name for m in loaded.models] == [expected]


def test_a_fuel_url_not_in_the_cache_is_a_located_error_saying_where_to_put_it(tmp_path):
    message = error_of(tmp_path, world_text(f"\n<include><uri>{FUEL}/7</uri></include>"),
                       env={"GZ_FUEL_CACHE_PATH": str(fuel_cache(tmp_path / "cache"))})
    assert re.search(r"w\.sdf:5:1: <include> 'https://fuel.gazebosim.org/1.0/OpenRobotics/"
                     r"models/Construction Cone/7' is not in the local Fuel cache, and models "
                     r"are not fetched from the network; searched: .*/cache/fuel.gazebosim.org/"
                     r"openrobotics/models/construction cone \(GZ_FUEL_CACHE_PATH\)\. Put the "
                     r"model there", message), message


@pytest.mark.parametrize("name", ["camera_sensor", "gpu_lidar_sensor", "sensors"])
def test_gz_sims_sensor_worlds_load_unchanged(tmp_path, name):
    """Their custom elements are kept, and their Fuel models come from the local cache (a
    stand-in the test puts there: the machine has no network)."""
    cache = tmp_path / "fuel"
    for model in ("construction cone", "playground"):
        folder = cache / "fuel.gazebosim.org" / "openrobotics" / "models" / model / "2"
        folder.mkdir(parents=True)
        (folder / "model.config").write_text(
            '<model><name>m</name><sdf version="1.6">model.sdf</sdf></model>')
        (folder / "model.sdf").write_text(
            '<sdf version="1.6">' + box_model(model.replace(" ", "_"), static=True) + "</sdf>")
    path = shared(*WORLDS, f"{name}.sdf")
    loaded = load_world_file(path, environ={"GZ_FUEL_CACHE_PATH": str(cache)})
    assert loaded.spec.compile().nbody > 2
    assert not [w for w in loaded.warnings if "custom element" in w or "gz:" in w]


def test_a_merged_include_adds_its_links_joints_and_plugins_to_the_model(tmp_path):
    """`<include merge="true">` (SDFormat 1.9): no nested scope, so the parent's joints and
    the included plugins name the included links and joints as they are."""
    folder = tmp_path / "models" / "wheel_kit"
    folder.mkdir(parents=True)
    (folder / "model.config").write_text('<model><sdf version="1.9">model.sdf</sdf></model>')
    (folder / "model.sdf").write_text("""<sdf version="1.9"><model name="wheel_kit">
      <link name="hub"><pose>0.5 0 0 0 0 0</pose><inertial><mass>1</mass></inertial></link>
      <link name="wheel"><pose>0.5 0 0 0 0 0</pose><inertial><mass>1</mass></inertial></link>
      <joint name="axle" type="revolute"><parent>hub</parent><child>wheel</child>
        <axis><xyz>0 1 0</xyz></axis></joint>
      <plugin filename="gz-sim-joint-position-controller-system"
        name="gz::sim::systems::JointPositionController"><joint_name>axle</joint_name></plugin>
    </model></sdf>""")
    env = {"GZ_SIM_RESOURCE_PATH": str(tmp_path / "models")}
    loaded = load(tmp_path, world_text("""
      <model name="cart"><link name="body"><inertial><mass>5</mass></inertial></link>
        <include merge="true"><uri>model://wheel_kit</uri><pose>0 0 0.2 0 0 0</pose></include>
        <joint name="mount" type="fixed"><parent>body</parent><child>hub</child></joint>
      </model>"""), env=env)
    (cart,) = loaded.models
    assert [p.name for p in cart.plugins] == ["gz::sim::systems::JointPositionController"]
    model = loaded.spec.compile()
    assert model.joint("cart/axle").id >= 0  # not cart/wheel_kit::axle
    hub = model.body("cart/hub").id
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    assert data.xpos[hub] == pytest.approx([0.5, 0, 0.2])  # the include's pose, then its own
