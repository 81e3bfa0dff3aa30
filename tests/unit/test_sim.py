"""The world with real MuJoCo, stepped in-process; the bus is replaced by a recording stand-in."""

from __future__ import annotations

import math
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from launcher.errors import LaunchError
from launcher.sim.pacing import Pacer
from launcher.sim.resources import find_world, resolve_uri
from launcher.sim.templates import Templates
from launcher.sim.transform import pose_from
from launcher.sim.world import SpawnError, World
from tests.support.sim import IDENTITY, make_world

DATA = Path(__file__).resolve().parent.parent / "data"
ROBOT = DATA / "diffbot.urdf"




def twist(v, w):
    return SimpleNamespace(linear=SimpleNamespace(x=v), angular=SimpleNamespace(z=w))




def run_for(world: World, seconds: float, command=None, name="bot") -> None:
    """Step for `seconds` of sim time, repeating `command` at 10 Hz as a driver would."""
    end = world.data.time + seconds
    next_command = world.data.time
    while world.data.time < end - 1e-9:
        if command is not None and world.data.time >= next_command:
            world.transport.callbacks[f"/model/{name}/cmd_vel"](command)
            next_command += 0.1
        world.physics.step(world.physics.steps_until_update(100))


@pytest.fixture
def world():
    return make_world()


def spawn_bot(world, name="bot", x=0.0, y=0.0, yaw=0.0, allow_renaming=False):
    position, quat = pose_from([x, y, 0.06, 0, 0, yaw])
    return world.spawn(world.templates.from_file(str(ROBOT)), name, position, quat,
                       allow_renaming)


# --- finding worlds and resources -----------------------------------------------------------
def test_worlds_are_found_as_paths_then_resource_folders_then_built_in(tmp_path, monkeypatch):
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    (tmp_path / "b" / "arena.xml").write_text("<mujoco model='arena'/>")
    monkeypatch.setenv("MUJOCO_SIM_RESOURCE_PATH", f"{tmp_path / 'a'}:{tmp_path / 'b'}")
    assert find_world("arena.xml") == (tmp_path / "b" / "arena.xml").resolve()
    assert find_world(str(tmp_path / "b" / "arena.xml")).name == "arena.xml"
    assert find_world("empty.xml").name == "empty.xml"
    with pytest.raises(LaunchError) as error:
        find_world("arena2.xml")
    text = str(error.value)
    assert "world 'arena2.xml' not found; searched:" in text
    assert str(tmp_path / "a") in text and str(tmp_path / "b") in text
    assert "built-in worlds" in text and "did you mean 'arena.xml'" in text


def test_a_template_world_renders_its_arguments_and_names_an_undefined_one(tmp_path):
    path = tmp_path / "arena.xml.j2"
    path.write_text('<mujoco model="{{ name }}"><worldbody>\n'
                    '<geom type="box" size="{{ size }} {{ size }} 0.1"/></worldbody></mujoco>\n')
    world = make_world(path=path, name="arena", size="3")
    assert world.world_name == "arena"
    assert world.model.geom_size[0][0] == pytest.approx(3.0)
    with pytest.raises(LaunchError) as error:
        make_world(path=path, name="arena")
    assert "'size' is undefined" in str(error.value) and "--world-arg" in str(error.value)


def test_an_mjcf_that_does_not_compile_names_file_and_line(tmp_path):
    path = tmp_path / "bad.xml"
    path.write_text('<mujoco model="bad">\n<worldbody>\n<geom type="sphere" size="-1"/>\n'
                    '<bogus/>\n</worldbody>\n</mujoco>\n')
    with pytest.raises(LaunchError) as error:
        make_world(path=path)
    assert str(path) in str(error.value) and "line 4" in str(error.value).lower()


def test_model_uris_resolve_through_model_config(tmp_path, monkeypatch):
    folder = tmp_path / "models" / "crate"
    folder.mkdir(parents=True)
    (folder / "model.config").write_text("<model><name>crate</name><mjcf>crate.xml</mjcf>"
                                         "</model>")
    (folder / "crate.xml").write_text('<mujoco model="crate"><worldbody><body name="box">'
                                      '<geom type="box" size=".2 .2 .2"/></body></worldbody>'
                                      "</mujoco>")
    monkeypatch.setenv("MUJOCO_SIM_RESOURCE_PATH", str(tmp_path / "models"))
    assert resolve_uri("model://crate", None) == folder / "crate.xml"
    assert resolve_uri("model://crate/model.config", None) == folder / "model.config"
    with pytest.raises(LaunchError) as error:
        resolve_uri("model://crat", None)
    assert "did you mean 'crate'" in str(error.value)
    world = make_world()
    entity = world.spawn_file("model://crate", "crate", (1, 2, 0.2, 0, 0, 0))
    assert world.data.xpos[entity.body] == pytest.approx([1, 2, 0.2])


# --- URDF ---------------------------------------------------------------------------------------
def test_a_urdf_keeps_fixed_links_and_visuals_and_gets_a_free_joint(world):
    entity = spawn_bot(world)
    names = [world.model.body(i).name for i in range(world.model.nbody)]
    assert "bot/caster" in names and "bot/lidar" in names  # fixed links are not fused away
    visual = [i for i in range(world.model.ngeom) if world.model.geom_contype[i] == 0]
    assert len(visual) >= 2  # the base's and the lidar's visuals stay
    assert entity.qpos >= 0  # a free joint at its root


@pytest.mark.parametrize("text, expected", [
    ("<robot name='r'><link name='a'>", "1:"),
    ("<robot name='r'><link name='a'/><link name='b'/></robot>", "2 root links (a, b)"),
    ("<robot name='r'><link name='a'/><link name='b'/>"
     "<joint name='j1' type='fixed'><parent link='a'/><child link='b'/></joint>"
     "<joint name='j2' type='fixed'><parent link='b'/><child link='a'/></joint></robot>",
     "no root link: the joints form a loop"),
    ("<robot name='r'><link name='a'/><joint name='j' type='fixed'><parent link='a'/>"
     "<child link='c'/></joint></robot>", "names link 'c', which is not defined"),
    ("<model/>", "expected URDF (<robot>), SDF (<sdf>) or MJCF"),
])
def test_invalid_urdf_is_a_clear_error(text, expected):
    with pytest.raises(LaunchError) as error:
        Templates().from_string(text, "robot.urdf")
    assert "robot.urdf" in str(error.value) and expected in str(error.value)


def test_a_missing_mesh_names_the_uri_and_where_it_looked(tmp_path):
    text = ("<robot name='r'><link name='a'><visual><geometry>"
            "<mesh filename='meshes/gone.stl'/></geometry></visual></link></robot>")
    (tmp_path / "r.urdf").write_text(text)
    with pytest.raises(LaunchError) as error:
        Templates().from_file(str(tmp_path / "r.urdf"))
    assert "'meshes/gone.stl' not found" in str(error.value)
    assert str(tmp_path / "meshes" / "gone.stl") in str(error.value)


def test_mesh_uris_resolve_and_templates_are_cached(tmp_path):
    (tmp_path / "meshes").mkdir()
    (tmp_path / "meshes" / "cube.obj").write_text(
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n")
    text = ("<robot name='r'><link name='a'><inertial><mass value='1'/><inertia ixx='1' "
            "iyy='1' izz='1' ixy='0' ixz='0' iyz='0'/></inertial><visual><geometry>"
            "<mesh filename='meshes/cube.obj'/></geometry></visual></link></robot>")
    (tmp_path / "r.urdf").write_text(text)
    descriptions = Templates()
    first = descriptions.from_file(str(tmp_path / "r.urdf"))
    assert descriptions.from_file(str(tmp_path / "r.urdf")) is first
    world = make_world()
    world.templates = descriptions
    world.spawn_file(str(tmp_path / "r.urdf"), "one", (0, 0, 1, 0, 0, 0))
    world.spawn_file(str(tmp_path / "r.urdf"), "two", (2, 0, 1, 0, 0, 0))
    assert world.model.nmesh >= 1


# --- spawning and removing -------------------------------------------------------------------
def state_of(world, entity):
    adr = entity.qpos
    return world.data.qpos[adr:adr + 7].copy(), world.data.qvel[entity.dof:entity.dof + 6].copy()


def test_spawn_and_remove_keep_everything_else_exactly(world):
    first = spawn_bot(world, "first")
    run_for(world, 0.5, twist(0.3, 0.5), "first")
    qpos, qvel = state_of(world, first)
    time_before = world.data.time
    second = spawn_bot(world, "second", x=2.0)
    after_qpos, after_qvel = state_of(world, world.entities["first"])
    assert np.array_equal(qpos, after_qpos) and np.array_equal(qvel, after_qvel)
    assert world.data.time == time_before
    assert second.qpos != first.qpos or second.name != first.name
    run_for(world, 0.2)
    qpos, qvel = state_of(world, world.entities["first"])
    time_before = world.data.time
    world.remove("second")
    assert "second" not in world.entities
    assert [world.model.body(i).name for i in range(world.model.nbody)
            if world.model.body(i).name.startswith("second/")] == []
    after_qpos, after_qvel = state_of(world, world.entities["first"])
    assert np.array_equal(qpos, after_qpos) and np.array_equal(qvel, after_qvel)
    assert world.data.time == time_before
    run_for(world, 0.2, twist(0.3, 0.0), "first")  # the plugins were re-bound
    assert world.transport.published["/model/first/odometry"]


def test_a_duplicate_name_is_refused_or_renamed_and_a_failed_spawn_changes_nothing(world):
    spawn_bot(world, "bot")
    run_for(world, 0.1)
    nbody, qpos, time = world.model.nbody, world.data.qpos.copy(), world.data.time
    with pytest.raises(SpawnError) as error:
        spawn_bot(world, "bot")
    assert "already exists" in str(error.value)
    with pytest.raises(LaunchError):
        world.spawn(world.templates.from_string("<robot name='r'><link name='a'>"
                                                   "<visual><geometry><box size='-1 1 1'/>"
                                                   "</geometry></visual></link></robot>"),
                    "broken", [0, 0, 1], IDENTITY)
    assert world.model.nbody == nbody and np.array_equal(world.data.qpos, qpos)
    assert world.data.time == time and list(world.entities) == ["bot"]
    assert spawn_bot(world, "bot", allow_renaming=True).name == "bot_1"
    run_for(world, 0.1)  # the world still steps


@pytest.mark.parametrize("pose", [[math.nan, 0, 0], [0, math.inf, 0]])
def test_a_nan_or_infinite_pose_is_refused(world, pose):
    with pytest.raises(SpawnError) as error:
        world.spawn(world.templates.from_file(str(ROBOT)), "bot", pose, IDENTITY)
    assert "finite" in str(error.value)
    assert not world.entities


def test_set_pose_moves_an_entity_and_unknown_names_get_a_suggestion(world):
    spawn_bot(world, "bot")
    world.placement.set_pose("bot", [3.0, -1.0, 0.5], IDENTITY)
    assert world.data.xpos[world.entities["bot"].body] == pytest.approx([3.0, -1.0, 0.5])
    with pytest.raises(SpawnError) as error:
        world.placement.set_pose("bto", [0, 0, 0], IDENTITY)
    assert "did you mean 'bot'" in str(error.value)


# --- diff drive, odometry ----------------------------------------------------------------------
def test_diff_drive_moves_at_omega_r_and_turns_the_right_way(world):
    spawn_bot(world)
    run_for(world, 0.5)
    start = world.data.xpos[world.entities["bot"].body].copy()
    run_for(world, 0.5, twist(0.5, 0.0))  # wheels reach ω = v / r = 10 rad/s
    begin, t0 = world.data.xpos[world.entities["bot"].body].copy(), world.data.time
    run_for(world, 2.0, twist(0.5, 0.0))
    moved = world.data.xpos[world.entities["bot"].body] - begin
    wheel = world.data.qvel[world.model.joint("bot/left_wheel_joint").dofadr[0]]
    speed = np.linalg.norm(moved[:2]) / (world.data.time - t0)
    assert speed == pytest.approx(wheel * 0.05, rel=0.05) and speed == pytest.approx(0.5, rel=0.05)
    assert moved[0] > 0.9 and abs(start[1] - begin[1]) < 0.01
    qpos = world.entities["bot"].qpos
    before = world.data.qpos[qpos + 3:qpos + 7].copy()
    run_for(world, 1.0, twist(0.0, 1.0))  # counter-clockwise, 1 rad/s
    after = world.data.qpos[qpos + 3:qpos + 7]
    yaw = [2 * math.atan2(q[3], q[0]) for q in (before, after)]
    turned = math.remainder(yaw[1] - yaw[0], 2 * math.pi)
    assert 0.7 < turned < 1.1


def test_odometry_agrees_with_the_true_pose_within_two_percent_over_five_metres(world):
    spawn_bot(world)
    run_for(world, 0.3)
    start = world.data.xpos[world.entities["bot"].body].copy()
    run_for(world, 11.0, twist(0.5, 0.05))
    odom = world.transport.published["/model/bot/odometry"][-1]
    true = world.data.xpos[world.entities["bot"].body] - start
    travelled = np.linalg.norm(true[:2])
    assert travelled > 5.0
    error = math.hypot(odom.pose.position.x - true[0], odom.pose.position.y - true[1])
    assert error / travelled < 0.02
    assert odom.header.frame_id == "bot/odom" and odom.child_frame_id == "bot/base_link"
    stamps = [m.header.stamp for m in world.transport.published["/model/bot/odometry"]]
    assert stamps == sorted(stamps) and np.diff(stamps[-10:]) == pytest.approx([0.02] * 9)


def test_the_watchdog_stops_the_wheels_when_cmd_vel_goes_silent(world):
    spawn_bot(world)
    world.transport.callbacks["/model/bot/cmd_vel"](twist(0.5, 0.0))
    run_for(world, 0.3)
    assert world.data.ctrl.any()
    run_for(world, 0.5)  # no command for 0.8 s > 0.5 s
    assert not world.data.ctrl.any()


def test_a_nan_cmd_vel_is_ignored_and_warned_once(world):
    spawn_bot(world)
    for _ in range(3):
        world.transport.callbacks["/model/bot/cmd_vel"](twist(math.nan, 0.0))
    run_for(world, 0.1)
    warnings = [m for m in world.transport.messages("warning") if "NaN" in m]
    assert len(warnings) == 1 and "'bot'" in warnings[0]
    assert not world.data.ctrl.any()


def test_ten_robots_spawned_by_name_are_driven_independently(world):
    for i in range(10):
        spawn_bot(world, f"r{i}", x=0.0, y=i * 1.0)
    run_for(world, 0.3)
    start = {n: world.data.xpos[e.body].copy() for n, e in world.entities.items()}
    end = world.data.time + 2.0
    while world.data.time < end:
        for i in range(10):
            world.transport.callbacks[f"/model/r{i}/cmd_vel"](twist(0.05 * i, 0.0))
        world.physics.step(world.physics.steps_until_update(100))
    for i in range(10):
        moved = world.data.xpos[world.entities[f"r{i}"].body][0] - start[f"r{i}"][0]
        assert moved == pytest.approx(0.1 * i, abs=0.04), f"r{i}"  # 0.1 m apart
    topics = [t for t in world.transport.published if t.endswith("/odometry")]
    assert len(topics) == 10


def test_joint_states_are_published_without_the_prefix(world):
    spawn_bot(world)
    run_for(world, 0.2, twist(0.5, 0.0))
    states = world.transport.published["/world/empty/model/bot/joint_state"]
    assert states[-1].joint_name == ["left_wheel_joint", "right_wheel_joint"]
    assert len(states[-1].position) == 2


# --- arms, plugins, resets, blow-ups ---------------------------------------------------------
ARM = """<robot name="arm">
  <link name="base"><inertial><mass value="5"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="upper"><inertial><origin xyz="0 0 0.2"/><mass value="0.5"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/>
    <axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="100" velocity="5"/></joint>
  <gazebo>
    <plugin filename="gz-sim-joint-position-controller-system" name="gz::sim::systems::JointPositionController">
      <joint_name>shoulder</joint_name><p_gain>20</p_gain><d_gain>2</d_gain>
    </plugin>
    <plugin filename="no-such-system" name="gz::sim::systems::Nothing"/>
  </gazebo>
</robot>"""


def test_a_position_controller_moves_an_arm_joint_and_an_unknown_plugin_is_logged(world):
    world.spawn(world.templates.from_string(ARM), "arm", [0, 0, 0.5], IDENTITY)
    errors = world.transport.messages("error")
    assert any("unknown plugin 'no-such-system'" in m for m in errors)
    world.transport.callbacks["/model/arm/joint/shoulder/0/cmd_pos"](SimpleNamespace(data=1.2))
    world.physics.step(3000)
    angle = world.data.qpos[world.model.joint("arm/shoulder").qposadr[0]]
    assert angle == pytest.approx(1.2, abs=0.02)


def test_joints_start_where_spawn_model_minus_j_puts_them_and_reset_returns_them(world):
    # gazebo_ros's spawn_model -J sets the model's joint positions once it is in
    world.spawn(world.templates.from_string(ARM), "arm", [0, 0, 0.5], IDENTITY,
                joints={"shoulder": 0.7})
    address = world.model.joint("arm/shoulder").qposadr[0]
    assert world.data.qpos[address] == pytest.approx(0.7)
    spawn_bot(world, "bot")  # another spawn (a recompile) keeps it
    assert world.data.qpos[world.model.joint("arm/shoulder").qposadr[0]] == pytest.approx(0.7)
    world.reset()
    assert world.data.qpos[world.model.joint("arm/shoulder").qposadr[0]] == pytest.approx(0.0)


@pytest.mark.parametrize("joints, expected", [
    ({"shouldr": 0.1}, "no joint named 'shouldr' (did you mean 'shoulder'?); its joints: "
                       "shoulder"),
    ({"shoulder": float("nan")}, "joint 'shoulder': position nan is not a finite number"),
])
def test_a_bad_joint_position_is_refused_and_nothing_is_spawned(world, joints, expected):
    with pytest.raises(LaunchError) as info:
        world.spawn(world.templates.from_string(ARM), "arm", [0, 0, 0.5], IDENTITY,
                    joints=joints)
    assert expected in str(info.value)
    assert "arm" not in world.entities


WHEEL = """<robot name="spinner">
  <link name="base"><inertial><mass value="5"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="disc"><inertial><mass value="0.5"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="spin" type="continuous"><parent link="base"/><child link="disc"/><axis xyz="0 0 1"/></joint>
  <mujoco><plugin filename="joint_velocity_controller"><joint_name>spin</joint_name>
    <p_gain>5</p_gain><topic>spin_speed</topic></plugin></mujoco>
</robot>"""


def test_the_mujoco_tag_form_and_a_velocity_controller(world):
    world.spawn(world.templates.from_string(WHEEL), "spinner", [0, 0, 0.5], IDENTITY)
    world.transport.callbacks["/model/spinner/spin_speed"](SimpleNamespace(data=3.0))
    world.physics.step(2000)
    speed = world.data.qvel[world.model.joint("spinner/spin").dofadr[0]]
    assert speed == pytest.approx(3.0, rel=0.02)


PLUGIN = '''
from launcher.sim.plugins import Plugin

class SpawnCrate(Plugin):
    def load(self):
        x = float(self.text("x", "5"))
        self.sim.spawn_file(self.text("model"), "crate", (x, 4, 0.2, 0, 0, 0))
        self.steps = 0

    def post_step(self, model, data):
        self.steps += 1

class Broken(Plugin):
    def post_step(self, model, data):
        raise RuntimeError("wheels fell off")

class LoadOnly(Plugin):
    def load(self):
        self.sim.spawn_file(self.text("model"), "crate", (5, 4, 0.2, 0, 0, 0))
'''


def plugin_world(tmp_path, monkeypatch, plugins: str):
    """A world with `plugins` (PLUGIN's classes on the plugin path; `{crate}` is a crate's
    model file) on a plane."""
    (tmp_path / "plugins").mkdir()
    (tmp_path / "plugins" / "crate_spawner.py").write_text(PLUGIN)
    (tmp_path / "crate.xml").write_text('<mujoco model="crate"><worldbody><body name="box">'
                                        '<geom type="box" size=".2 .2 .2"/></body></worldbody>'
                                        "</mujoco>")
    monkeypatch.setenv("MUJOCO_SIM_PLUGIN_PATH", str(tmp_path / "plugins"))
    world_file = tmp_path / "w.xml"
    world_file.write_text(f"""<mujoco model="w">{plugins.format(crate=tmp_path / 'crate.xml')}
  <worldbody><geom type="plane" size="0 0 1"/></worldbody>
</mujoco>""")
    return make_world(path=world_file)


def test_world_plugins_load_with_their_config_spawn_and_a_raising_one_is_dropped(
        tmp_path, monkeypatch):
    world = plugin_world(tmp_path, monkeypatch, """
  <plugin filename="crate_spawner" name="SpawnCrate">
    <model>{crate}</model><x>5</x>
  </plugin>
  <plugin filename="crate_spawner.py" name="Broken"/>
  <plugin filename="crate_spawner.py" name="Missing"/>""")
    assert "crate" in world.entities
    assert world.data.xpos[world.entities["crate"].body][:2] == pytest.approx([5, 4])
    world.physics.step(5)
    world.physics.step(5)
    errors = world.transport.messages("error")
    assert any("has no class 'Missing'" in m for m in errors)
    assert sum("plugin Broken raised in post_step: RuntimeError: wheels fell off" in m
               for m in errors) == 1
    assert [p.label for p in world.plugins.world] == ["SpawnCrate"] and \
        world.plugins.world[0].steps == 2


def test_a_plugin_without_post_step_does_not_cut_the_batches(tmp_path, monkeypatch):
    """The seed's crate dropper spawns at load and has no post_step: batches stay whole
    (it made every batch one step: the sim at half the speed of raw mj_step)."""
    world = plugin_world(tmp_path, monkeypatch, """
  <plugin filename="crate_spawner" name="LoadOnly"><model>{crate}</model></plugin>""")
    assert "crate" in world.entities
    assert world.physics.steps_until_update(100) == 100


def test_resets_all_time_only_and_poses_only(world):
    spawn_bot(world)
    run_for(world, 1.0, twist(0.5, 0.0))
    qpos = world.data.qpos.copy()
    assert world.data.xpos[world.entities["bot"].body][0] > 0.2
    world.reset(time=True, poses=False)
    assert world.data.time == 0.0 and world.physics.iterations == 0
    assert np.array_equal(world.data.qpos, qpos)
    run_for(world, 0.2)
    time_before = world.data.time
    world.reset(time=False, poses=True)
    assert world.data.time == time_before > 0.19
    assert world.data.xpos[world.entities["bot"].body][0] == pytest.approx(0.0, abs=1e-6)
    run_for(world, 0.2, twist(0.5, 0.0))
    world.reset()
    assert world.data.time == 0.0
    assert world.data.xpos[world.entities["bot"].body][:2] == pytest.approx([0, 0], abs=1e-6)


def test_a_physics_blow_up_is_reported_with_the_entity_and_the_world_goes_on(
        world, tmp_path, monkeypatch):
    from launcher.sim.server import route_mujoco_warnings

    monkeypatch.chdir(tmp_path)
    route_mujoco_warnings(world.transport.logger)  # as the server sets up
    spawn_bot(world, "wild")
    entity = world.entities["wild"]
    world.data.qvel[entity.dof + 6] = 1e30  # the left wheel
    world.physics.step(1)
    warnings = world.transport.messages("warning")
    assert any("unstable" in m and "entity 'wild'" in m for m in warnings), warnings
    assert any(m.startswith("MuJoCo: Nan, Inf or huge value") for m in warnings)
    assert not (tmp_path / "MUJOCO_LOG.TXT").exists()  # not written into the user's folder
    run_for(world, 0.1)
    assert np.isfinite(world.data.qpos).all()


def test_the_warning_indices_the_step_loop_reads():
    from launcher.sim.stepping import UNSTABLE

    assert [int(kind) for kind in UNSTABLE] == [3, 4, 5]


def test_the_world_state_plugin_and_mjcf_robots(world):
    world.spawn(world.templates.from_string(
        '<mujoco model="ball"><worldbody><body name="b"><geom size=".1"/></body></worldbody>'
        "</mujoco>"), "ball", [0, 0, 1], IDENTITY)
    assert world.entities["ball"].qpos >= 0  # it got a free joint and falls
    world.physics.step(200)
    assert world.data.xpos[world.entities["ball"].body][2] < 1.0


# --- the loop and the world's services (runner.py, world_services.py) -------------------------
class LoopNode:
    """Stands in for the sim's node: its endpoints record, and each request a test queues runs
    at a `spin_once` of the loop, as the bus's callbacks do; `on_idle` is told when the loop
    would wait for more."""

    def __init__(self, world) -> None:
        self.logger = world.transport.logger
        self.queue: list = []
        self.on_idle = lambda: None
        self.services: dict[str, object] = {}
        self.published: dict[str, list] = {}

    def get_logger(self):
        return self.logger

    def create_publisher(self, type_name, topic, qos=10, **_):
        box = self.published.setdefault(topic, [])
        return SimpleNamespace(get_subscription_count=lambda: 1, publish_raw=box.append,
                               destroy=lambda: self.published.pop(topic, None))

    def create_service(self, type_name, name, callback):
        self.services[name] = callback
        return SimpleNamespace(deferred=False, destroy=lambda: self.services.pop(name, None))

    def message(self, type_name, **fields):  # (a request's fields have their defaults)
        return control(**fields) if type_name.endswith("Control_Request") else \
            SimpleNamespace(**fields)

    def spin_once(self, timeout=None) -> bool:
        if not self.queue:
            if timeout:
                self.on_idle()
            return False
        self.queue.pop(0)()
        return True


def control(**asked):
    fields = dict(pause=False, step=False, multi_step=0, reset_all=False,
                  reset_time_only=False, reset_model_only=False)
    return SimpleNamespace(**{**fields, **asked})


def a_sim(world, running=False):
    from launcher.sim.runner import SimulationRunner
    from launcher.sim.world_services import WorldServices

    node = LoopNode(world)
    runner = SimulationRunner(world, node, 0.0, running)
    return node, runner, WorldServices(runner)


def test_a_multi_step_is_stepped_by_the_loop_in_batches_after_its_answer(world):
    node, runner, _ = a_sim(world)
    answers = []
    on_control = node.services["/world/empty/control"]
    node.queue.append(lambda: answers.append(on_control(control(pause=True, multi_step=250),
                                                        SimpleNamespace())))
    node.on_idle = runner.stop  # (once the 250 are done, nothing else comes)
    runner.run()
    assert answers[0].message == "paused; stepping 250"
    assert world.physics.iterations == 250 and runner.steps_to_go == 0 and runner.paused
    assert len(node.published["/world/empty/clock"]) >= 4  # a clock after every batch


def test_a_later_request_replaces_the_steps_still_to_go_and_a_reset_keeps_a_pause(world):
    node, runner, services = a_sim(world)
    told = []
    runner.step_then(1000, told.append)
    services.on_page_action("step")  # the page's Step: one step, in place of the 1000
    assert told == [False] and runner.steps_to_go == 1 and runner.paused
    assert services.on_control(control(reset_all=True), SimpleNamespace()).message == "paused"
    assert runner.paused and runner.steps_to_go == 0
    refused = services.on_control(control(pause=True, multi_step=10**9), SimpleNamespace())
    assert not refused.success and "past the limit of 100,000,000" in refused.message
    assert services.on_control(control(), SimpleNamespace()).message == "running"
    assert not runner.paused


def test_a_loaded_world_moves_the_services_and_clock_and_fails_the_spawns_waiting(world):
    node, runner, services = a_sim(world)
    followed, told = [], []
    runner.on_load = lambda loaded, renamed: (services.follow(loaded, renamed),
                                              followed.append(renamed))
    runner.spawn_soon(None, told.append)
    runner.load(make_world("<mujoco model='arena'><worldbody/></mujoco>"))
    assert followed == [True] and runner.paused and runner.world.world_name == "arena"
    assert isinstance(told[0], SpawnError) and "replaced" in str(told[0])
    assert "/world/arena/control" in node.services and "/world/empty/control" not in node.services
    assert "/world/arena/clock" in node.published and "/world/empty/clock" not in node.published
    services.close()


# --- pacing ------------------------------------------------------------------------------------
def test_the_pacer_never_drifts_and_reanchors_after_a_stall():
    now = [0.0]
    pacer = Pacer(0.001, 1.0, clock=lambda: now[0])
    total = 0
    for _ in range(600_000):  # ten minutes of 1 ms ticks with a little jitter
        now[0] += 0.001 + (3e-7 if total % 2 else -3e-7)
        due = pacer.due()
        pacer.stepped(due)
        total += due
    assert abs(total - 600_000) <= 1
    now[0] += 5.0  # a stall
    assert pacer.due() == 1 and pacer.reanchors == 1
    fast = Pacer(0.001, 2.0, clock=lambda: now[0])
    now[0] += 0.1
    assert fast.due() == 200
    assert Pacer(0.001, 0.0).due() > 1_000_000


def test_encode_png_round_trips_the_pixels():
    import struct
    import zlib

    from launcher.sim.snapshot import encode_png

    pixels = np.arange(4 * 3 * 3, dtype=np.uint8).reshape(4, 3, 3)
    data = encode_png(pixels)
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    assert struct.unpack(">IIBB", data[16:26]) == (3, 4, 8, 2)  # width, height, 8-bit RGB
    idat = data.index(b"IDAT")
    rows = zlib.decompress(data[idat + 4:idat + 4 + struct.unpack(">I", data[idat - 4:idat])[0]])
    assert rows == b"".join(b"\x00" + pixels[r].tobytes() for r in range(4))
    assert data.endswith(b"IEND\xaeB`\x82")


@pytest.mark.parametrize("given, expected", [("", "default"), ("MuJoCo Model", "default"),
                                             ("arena", "arena"), ("my world", "my_world"),
                                             ("2d-room", "_2d_room")])
def test_world_names_are_valid_topic_name_parts(given, expected):
    from launcher.sim.world import world_name

    assert world_name(given) == expected


def _arm_with(plugin: str) -> str:
    return ARM.replace(
        "<joint_name>shoulder</joint_name><p_gain>20</p_gain><d_gain>2</d_gain>", plugin)


def _run(world, steps: int) -> None:
    """Step as the sim's loop does: in batches that end where a plugin is due."""
    while steps > 0:
        batch = world.physics.steps_until_update(steps)
        world.physics.step(batch)
        steps -= batch


def _shoulder(world) -> float:
    return world.data.qpos[world.model.joint("arm/shoulder").qposadr[0]]


def test_joint_position_controller_topics_are_gz_sims():
    """<topic> is used as given (not under /model/…), <sub_topic> goes under the model."""
    for element, topic in (("<topic>custom/cmd</topic>", "/custom/cmd"),
                           ("<topic>/abs/cmd</topic>", "/abs/cmd"),
                           ("<sub_topic>arm_cmd</sub_topic>", "/model/arm/arm_cmd"),
                           ("<joint_index>0</joint_index>", "/model/arm/joint/shoulder/0/cmd_pos")):
        world = make_world()
        world.spawn(world.templates.from_string(_arm_with(
            f"<joint_name>shoulder</joint_name>{element}")), "arm", [0, 0, 0.5], IDENTITY)
        assert topic in world.transport.callbacks, (element, list(world.transport.callbacks))


def test_joint_position_controller_integral_term_and_offset_are_honoured():
    """A constant offset force holds the joint off its target by offset/p with no integral
    term; gz-sim's i_gain (bounded by i_max/i_min) takes that error away."""
    errors = {}
    for i_gain in (0.0, 20.0):
        world = make_world()
        world.spawn(world.templates.from_string(_arm_with(
            f"<joint_name>shoulder</joint_name><p_gain>20</p_gain><d_gain>2</d_gain>"
            f"<i_gain>{i_gain}</i_gain><i_max>10</i_max><i_min>-10</i_min>"
            f"<cmd_offset>2</cmd_offset>")), "arm", [0, 0, 0.5], IDENTITY)
        world.transport.callbacks["/model/arm/joint/shoulder/0/cmd_pos"](
            SimpleNamespace(data=0.5))
        _run(world, 8000)
        errors[i_gain] = _shoulder(world) - 0.5
    assert errors[0.0] == pytest.approx(2 / 20, abs=0.01)
    assert abs(errors[20.0]) < 0.01


def test_joint_position_controller_velocity_commands_are_bounded_by_cmd_max():
    world = make_world()
    world.spawn(world.templates.from_string(_arm_with(
        "<joint_name>shoulder</joint_name><use_velocity_commands>true</use_velocity_commands>"
        "<cmd_max>0.5</cmd_max>")), "arm", [0, 0, 0.5], IDENTITY)
    world.transport.callbacks["/model/arm/joint/shoulder/0/cmd_pos"](SimpleNamespace(data=1.0))
    _run(world, 1000)
    assert _shoulder(world) == pytest.approx(0.5, abs=0.05)  # 0.5 rad/s for 1 s
    _run(world, 2000)
    assert _shoulder(world) == pytest.approx(1.0, abs=0.01)


def test_a_urdf_rooted_at_a_world_link_is_anchored_as_gazebo_anchors_it(world):
    """Gazebo fixes a URDF whose root link is `world` to the world: no free joint, no fall."""
    anchored = """<robot name="post"><link name="world"/>
      <link name="top"><inertial><mass value="1"/><inertia ixx="0.1" iyy="0.1" izz="0.1"
      ixy="0" ixz="0" iyz="0"/></inertial></link>
      <joint name="fix" type="fixed"><parent link="world"/><child link="top"/>
      <origin xyz="0 0 1"/></joint></robot>"""
    world.spawn(world.templates.from_string(anchored), "post", [2, 0, 0], IDENTITY)
    world.physics.step(500)
    assert list(world.data.xpos[world.model.body("post/top").id]) == pytest.approx([2, 0, 1])
    assert all(world.model.jnt_type[j] != 0 for j in range(world.model.njnt))  # none free


def test_a_link_moving_on_an_anchored_part_does_not_collide_with_it(world):
    """A cart on a rail fixed to `world` overlaps the rail, as gz_ros2_control's cart does;
    Gazebo never collides a model's own links, so the cart slides freely."""
    box = '<collision><geometry><box size="{}"/></geometry></collision><inertial>' \
          '<mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>'
    cart = f"""<robot name="cart"><link name="world"/>
      <link name="rail">{box.format("30 0.05 0.05")}</link>
      <link name="cart">{box.format("0.5 0.5 0.2")}</link>
      <joint name="fix" type="fixed"><parent link="world"/><child link="rail"/>
      <origin xyz="0 0 1"/></joint>
      <joint name="slide" type="prismatic"><parent link="rail"/><child link="cart"/>
      <axis xyz="1 0 0"/><limit lower="-15" upper="15" effort="100" velocity="30"/></joint>
      </robot>"""
    world.spawn(world.templates.from_string(cart), "cart", [0, 0, 0], IDENTITY)
    world.data.qvel[world.model.jnt_dofadr[world.model.joint("cart/slide").id]] = 1.0
    world.physics.step(1000)
    assert world.data.ncon == 0
    slide = world.model.jnt_qposadr[world.model.joint("cart/slide").id]
    assert world.data.qpos[slide] == pytest.approx(1.0, abs=0.02)  # 1 m/s for 1 s, unbraked


KEYED = """<mujoco model="keyed"><worldbody>
  <body name="ball" pos="0 0 1"><freejoint/><geom size="0.1"/></body>
</worldbody><keyframe><key name="high" qpos="0 0 3 1 0 0 0"/></keyframe></mujoco>"""


def test_a_world_starts_from_its_keyframe_and_resets_to_it(tmp_path):
    world = make_world(KEYED, tmp_path / "keyed.xml")
    world.start_from("high")
    assert world.data.qpos[2] == pytest.approx(3.0)
    run_for(world, 0.3, name="ball")
    assert world.data.qpos[2] < 3.0
    world.reset(time=False, poses=True)
    assert world.data.qpos[2] == pytest.approx(3.0) and world.data.time > 0
    run_for(world, 0.3, name="ball")
    world.reset()
    assert world.data.qpos[2] == pytest.approx(3.0) and world.data.time == 0.0


def test_a_keyframe_the_world_lacks_names_the_nearest(tmp_path):
    world = make_world(KEYED, tmp_path / "keyed.xml")
    with pytest.raises(LaunchError) as caught:
        world.start_from("hihg")
    assert "no keyframe 'hihg' in the world (did you mean 'high'?); its keyframes: high" in \
        str(caught.value)
    assert world.keyframe == "" and world.data.qpos[2] == pytest.approx(1.0)


KEYED_ROBOT = """<mujoco model="arm"><worldbody><body name="base"><geom size="0.1" mass="1"/>
  <body name="link" pos="0 0 0.2"><joint name="elbow" axis="0 1 0"/>
    <geom type="capsule" size="0.02 0.1" mass="0.5"/></body></body></worldbody>
<keyframe><key name="bent" qpos="0.8"/></keyframe></mujoco>"""


def test_a_robot_spawned_from_its_keyframe_starts_there_and_resets_to_it(world, tmp_path):
    path = tmp_path / "arm.xml"
    path.write_text(KEYED_ROBOT)
    world.spawn(world.templates.from_file(str(path)), "arm", [2, 0, 0.5], [1, 0, 0, 0],
                keyframe="bent")
    elbow = world.model.jnt_qposadr[world.model.joint("arm/elbow").id]
    root = world.model.jnt_qposadr[world.model.joint(world.model.body("arm/base")
                                                     .jntadr[0]).id]
    assert world.data.qpos[elbow] == pytest.approx(0.8)
    assert world.data.qpos[root:root + 3] == pytest.approx([2, 0, 0.5])  # its pose: the spawn's
    world.data.qpos[elbow] = -0.3
    world.reset()
    assert world.data.qpos[elbow] == pytest.approx(0.8)


def test_a_keyframe_the_robot_lacks_refuses_the_spawn_naming_the_nearest(world, tmp_path):
    path = tmp_path / "arm.xml"
    path.write_text(KEYED_ROBOT)
    with pytest.raises(LaunchError) as caught:
        world.spawn(world.templates.from_file(str(path)), "arm", [2, 0, 0.5], [1, 0, 0, 0],
                    keyframe="bnet")
    assert "no keyframe 'bnet' in the description (did you mean 'bent'?); its keyframes: bent" \
        in str(caught.value)
    assert "arm" not in world.entities
