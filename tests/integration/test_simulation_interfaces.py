"""ROS's standard simulator API (simulation_interfaces) on launcher's sim, through a client
that imports only rclpy and the package's interfaces, as one written for Gazebo (ros_gz's
`/gzserver/*`) would: real sim processes, real MuJoCo, real Zenoh. An SDF world and an MJCF
world alike; the bad inputs the issue lists answered with a Result, the sim running on."""

from __future__ import annotations

import json

import pytest

from tests.support.nodes import node_package, stop

WORLD = """
<sdf version="1.9"><world name="arena">
  <frame name="dock"><pose>1 2 0 0 0 1.5707963</pose></frame>
  <model name="wall"><static>true</static><pose>0 3 0.5 0 0 0</pose>
    <link name="l"><collision name="c"><geometry><box><size>2 0.2 1</size></box></geometry>
    </collision></link></model>
  <model name="ball"><pose>0 0 1 0 0 0</pose>
    <link name="l"><inertial><mass>1</mass></inertial><collision name="c"><geometry><sphere>
    <radius>0.1</radius></sphere></geometry></collision></link></model>
</world></sdf>
"""
MJCF_WORLD = """
<mujoco model="table_top">
  <worldbody>
    <site name="drop_zone" pos="0.5 0 0.8"/>
    <body name="table" pos="0 0 0.4"><geom type="box" size="0.6 0.4 0.4"/></body>
    <body name="cube" pos="0 0 0.9"><freejoint/><geom type="box" size="0.05 0.05 0.05"/></body>
  </worldbody>
</mujoco>
"""
CRATE = """
<sdf version="1.9"><model name="crate"><pose>0 0 0.25 0 0 0</pose><link name="body">
  <inertial><mass>2</mass></inertial><collision name="c"><geometry><box>
  <size>0.5 0.5 0.5</size></box></geometry></collision></link></model></sdf>
"""
CUBE = ("<mujoco model='cube'><worldbody><body name='b'><geom type='box' size='.1 .2 .3'/>"
        "</body></worldbody></mujoco>")

# The client's own imports: rclpy and simulation_interfaces, nothing of launcher's.
PROLOGUE = """
import json, time
import rclpy
from rclpy.node import Node
from rclpy.action import ActionClient
from geometry_msgs.msg import Pose, PoseStamped, Vector3
from simulation_interfaces.action import SimulateSteps
from simulation_interfaces.msg import (Bounds, EntityCategory, EntityFilters, EntityInfo,
    EntityState, Resource, SimulationState, SpawnEntity as SpawnRequest, TagsFilter)
from simulation_interfaces.srv import (DeleteEntity, GetAvailableWorlds, GetCurrentWorld,
    GetEntities, GetEntitiesStates, GetEntityBounds, GetEntityInfo, GetEntityState,
    GetNamedPoseBounds, GetNamedPoses, GetSimulationState, GetSimulatorFeatures,
    GetSpawnables, LoadWorld, ResetSimulation, SetEntityInfo, SetEntityState,
    SetSimulationState, SpawnEntities, SpawnEntity, StepSimulation, UnloadWorld)
rclpy.init()
node = Node("standard_api_client")

def call(service, kind, **fields):
    client = node.create_client(kind, "/gzserver/" + service)
    assert client.wait_for_service(timeout_sec=30), service
    future = client.call_async(kind.Request(**fields))
    rclpy.spin_until_future_complete(node, future, timeout_sec=60)
    return future.result()

def code(response):
    return [response.result.result, response.result.error_message]

def state():
    return call("get_simulation_state", GetSimulationState).state.state

def set_state(value):
    return code(call("set_simulation_state", SetSimulationState,
                     state=SimulationState(state=value)))

def entity_state(name):
    return call("get_entity_state", GetEntityState, entity=name).state

def position(name):
    p = entity_state(name).pose.position
    return [round(p.x, 4), round(p.y, 4), round(p.z, 4)]

def seconds(name="wall"):
    stamp = entity_state(name).header.stamp
    return round(stamp.sec + stamp.nanosec * 1e-9, 6)

def entities(**filters):
    return sorted(call("get_entities", GetEntities, filters=EntityFilters(**filters)).entities)

def pose(x=0.0, y=0.0, z=0.0, frame=""):
    stamped = PoseStamped()
    stamped.header.frame_id = frame
    stamped.pose.position.x, stamped.pose.position.y, stamped.pose.position.z = x, y, z
    stamped.pose.orientation.w = 1.0
    return stamped

def spawn(name, uri="", text="", **fields):
    fields.setdefault("initial_pose", pose())
    response = call("spawn_entity", SpawnEntity, name=name,
                    entity_resource=Resource(uri=uri, resource_string=text), **fields)
    return code(response) + [response.entity_name]

def out(**values):
    print("OUT " + json.dumps(values), flush=True)
"""


@pytest.fixture
def arena(ws):
    """The SDF world `arena`, paused, with the model folder `crate` on the resource path."""
    ws.own_bus()
    ws.write("arena.sdf", WORLD)
    ws.write("models/crate/model.config", "<model><name>crate</name><sdf version='1.9'>"
             "model.sdf</sdf><description>A wooden crate</description></model>")
    ws.write("models/crate/model.sdf", CRATE)
    ws.env["GZ_SIM_RESOURCE_PATH"] = str(ws.root / "models")
    proc = ws.start("sim", "-v", "3", "arena.sdf", output="sim.out")
    ws.wait_for_output("world 'arena'", 60, "sim.out")
    yield ws
    stop(proc)


def client(ws, body: str) -> dict:
    """Run a client program of PROLOGUE and `body` (a ROS node, as `ros2 run` runs it); what
    it printed with out()."""
    name = f"client_{len(list(ws.root.glob('ws/si_client/scripts/*')))}.py"
    node_package(ws, "si_client", {name: PROLOGUE + body})
    done = ws.run("run", "si_client", name, timeout=120)
    assert done.returncode == 0, done.stdout + done.stderr
    found: dict = {}
    for line in done.stdout.splitlines():
        if line.startswith("OUT "):
            found.update(json.loads(line[4:]))
    return found


def test_the_features_say_what_is_served_and_every_service_answers(arena):
    seen = client(arena, """
features = call("get_simulator_features", GetSimulatorFeatures).features
out(features=list(features.features), formats=list(features.spawn_formats))
""")
    assert {0, 1, 10, 11, 20, 23, 24, 25, 26, 31, 32, 33, 50} <= set(seen["features"])
    assert {40, 41, 43, 44, 45} <= set(seen["features"])  # LoadWorld and UnloadWorld too
    assert seen["formats"] == ["sdf", "urdf", "mjcf"]
    listed = arena.run("service", "list").stdout.split()
    for name in ("delete_entity", "get_available_worlds", "get_current_world", "get_entities",
                 "get_entities_states", "get_entity_bounds", "get_entity_info",
                 "get_entity_state", "get_named_pose_bounds", "get_named_poses",
                 "get_simulation_state", "get_simulator_features", "get_spawnables",
                 "load_world", "reset_simulation", "set_entity_info", "set_entity_state",
                 "set_simulation_state", "spawn_entities", "spawn_entity", "step_simulation",
                 "unload_world"):
        assert f"/gzserver/{name}" in listed, name
    assert "/gzserver/simulate_steps" in arena.run("action", "list").stdout


def test_the_simulation_state_moves_as_the_package_defines(arena):
    seen = client(arena, """
first = state()
paused = set_state(SimulationState.STATE_PAUSED)
after_pause = state()
playing = set_state(SimulationState.STATE_PLAYING)
again = set_state(SimulationState.STATE_PLAYING)
time.sleep(0.5)
ran = seconds()
stopped = set_state(SimulationState.STATE_STOPPED)
out(first=first, paused=paused[0], after_pause=after_pause, playing=playing[0],
    again=again, ran=ran, stopped=stopped[0], after_stop=state(), time=seconds(),
    no_world=set_state(SimulationState.STATE_NO_WORLD)[0])
""")
    assert seen["first"] == 0  # STATE_STOPPED: loaded, not stepped
    assert seen["after_pause"] == 2 and seen["paused"] == 1
    assert seen["again"][0] == 101 and "already" in seen["again"][1]  # ALREADY_IN_TARGET_STATE
    assert seen["ran"] > 0.1
    assert (seen["stopped"], seen["after_stop"], seen["time"]) == (1, 0, 0.0)
    assert seen["no_world"] == 103  # INCORRECT_TRANSITION


def test_step_simulation_answers_once_the_steps_are_done(arena):
    seen = client(arena, """
answer = code(call("step_simulation", StepSimulation, steps=250))
out(answer=answer, time=seconds(), state=state())
""")
    assert seen == {"answer": [1, ""], "time": 0.25, "state": 2}


def test_step_simulation_while_playing_is_refused_and_the_sim_plays_on(arena):
    seen = client(arena, """
set_state(SimulationState.STATE_PLAYING)
answer = code(call("step_simulation", StepSimulation, steps=10))
before = seconds()
time.sleep(0.3)
out(answer=answer, moved=seconds() > before, state=state())
""")
    assert seen["answer"][0] == 4 and "playing" in seen["answer"][1]  # OPERATION_FAILED
    assert seen["moved"] and seen["state"] == 1


def test_simulate_steps_gives_feedback_and_its_result(arena):
    seen = client(arena, """
actions = ActionClient(node, SimulateSteps, "/gzserver/simulate_steps")
assert actions.wait_for_server(timeout_sec=30)
feedback = []
sent = actions.send_goal_async(SimulateSteps.Goal(steps=1000),
                               feedback_callback=lambda m: feedback.append(
                                   [m.feedback.completed_steps, m.feedback.remaining_steps]))
rclpy.spin_until_future_complete(node, sent, timeout_sec=30)
ended = sent.result().get_result_async()
rclpy.spin_until_future_complete(node, ended, timeout_sec=60)
done = ended.result()
out(status=done.status, result=done.result.result.result, time=seconds(),
    feedback_sums=sorted({a + b for a, b in feedback}), some=len(feedback) > 0)
""")
    assert (seen["status"], seen["result"], seen["time"]) == (4, 1, 1.0)  # SUCCEEDED, OK
    assert seen["some"] and seen["feedback_sums"] == [1000]


def test_simulate_steps_is_canceled_on_request(arena):
    seen = client(arena, """
actions = ActionClient(node, SimulateSteps, "/gzserver/simulate_steps")
assert actions.wait_for_server(timeout_sec=30)
sent = actions.send_goal_async(SimulateSteps.Goal(steps=50_000_000))
rclpy.spin_until_future_complete(node, sent, timeout_sec=30)
handle = sent.result()
time.sleep(0.3)
canceling = handle.cancel_goal_async()
rclpy.spin_until_future_complete(node, canceling, timeout_sec=30)
ended = handle.get_result_async()
rclpy.spin_until_future_complete(node, ended, timeout_sec=30)
time_then = seconds()
time.sleep(0.3)
out(status=ended.result().status, stepped=time_then, still=seconds() == time_then,
    state=state())
""")
    assert seen["status"] == 5  # CANCELED
    assert 0 < seen["stepped"] < 50_000 and seen["still"] and seen["state"] == 2


def test_spawn_entity_from_a_model_uri_and_an_mjcf_string(arena):
    seen = client(arena, f"""
crate = spawn("crate", uri="model://crate", initial_pose=pose(2.0, -1.0, 0.5))
cube = spawn("", text={CUBE!r}, initial_pose=pose(1.0, 0.0, 0.0, frame="wall"))
out(crate=crate, at=position("crate"), cube=cube, cube_at=position("cube"),
    listed=entities())
""")
    assert seen["crate"] == [1, "", "crate"] and seen["at"] == [2.0, -1.0, 0.5]
    assert seen["cube"] == [1, "", "cube"]  # the description's own name
    assert seen["cube_at"] == [1.0, 3.0, 0.5]  # relative to the wall's frame
    assert seen["listed"] == ["ball", "crate", "cube", "wall"]


@pytest.mark.parametrize(("fields", "expected", "says"), [
    ({"name": "ball", "text": CUBE}, 101, "already exists"),  # NAME_NOT_UNIQUE
    ({"name": "bad name", "text": CUBE}, 102, "invalid entity name"),  # NAME_INVALID
    ({"name": "x", "text": "<scene/>"}, 103, "not a model description"),  # UNSUPPORTED_FORMAT
    ({"name": "x"}, 104, "nothing to spawn"),  # NO_RESOURCE
    ({"name": "x", "uri": "model://crat"}, 2, "did you mean 'crate'"),  # resolves nowhere
    ({"name": "x", "text": "<mujoco><worldbody><body>"}, 106, ""),  # RESOURCE_PARSE_ERROR
])
def test_spawn_entity_refuses_bad_requests_and_the_world_keeps_its_entities(
        arena, fields, expected, says):
    seen = client(arena, f"""
out(answer=spawn(**{fields!r}), listed=entities(), time=seconds())
""")
    assert seen["answer"][0] == expected and says in seen["answer"][1], seen
    assert seen["listed"] == ["ball", "wall"]


def test_spawn_entities_spawns_together_and_says_which_failed(arena):
    seen = client(arena, f"""
requests = [SpawnRequest(name=n, entity_resource=Resource(resource_string={CUBE!r}),
                         initial_pose=pose(float(i), 5.0, 1.0))
            for i, n in enumerate(["a", "b", "ball", "c"])]
response = call("spawn_entities", SpawnEntities, spawn_requests=requests)
out(answer=code(response), each=[[r.result.result, r.entity_name] for r in response.results],
    listed=entities())
""")
    assert seen["answer"][0] == 150 and "1 of 4" in seen["answer"][1]  # ENTITIES_SPAWN_FAILED
    assert seen["each"] == [[1, "a"], [1, "b"], [101, ""], [1, "c"]]
    assert seen["listed"] == ["a", "b", "ball", "c", "wall"]
    assert "3 entities spawned with one recompile" in arena.output("sim.out")


def test_delete_entity_removes_it_and_an_unknown_one_is_not_found(arena):
    seen = client(arena, """
out(deleted=code(call("delete_entity", DeleteEntity, entity="ball")), listed=entities(),
    unknown=code(call("delete_entity", DeleteEntity, entity="bal")))
""")
    assert seen["deleted"] == [1, ""] and seen["listed"] == ["wall"]
    assert seen["unknown"][0] == 2 and "no entity named 'bal'" in seen["unknown"][1]


def test_entity_filters_by_name_category_tags_and_bounds(arena):
    seen = client(arena, """
info = EntityInfo(category=EntityCategory(category=EntityCategory.CATEGORY_ROBOT),
                  description="a ball", tags=["round", "red"])
tagged = code(call("set_entity_info", SetEntityInfo, entity="ball", info=info))
def sphere(x, y, z, r):
    return Bounds(type=Bounds.TYPE_SPHERE, points=[Vector3(x=x, y=y, z=z), Vector3(x=r)])
def hull(*points):
    return Bounds(type=Bounds.TYPE_CONVEX_HULL,
                  points=[Vector3(x=float(x), y=float(y), z=float(z)) for x, y, z in points])
states = call("get_entities_states", GetEntitiesStates, filters=EntityFilters(filter="b.*"))
out(tagged=tagged, pattern=entities(filter="w.*"),
    static=entities(categories=[EntityCategory(category=EntityCategory.CATEGORY_STATIC_OBJECT)]),
    robots=entities(categories=[EntityCategory(category=EntityCategory.CATEGORY_ROBOT)]),
    any_tag=entities(tags=TagsFilter(tags=["red", "blue"])),
    all_tags=entities(tags=TagsFilter(tags=["red", "blue"], filter_mode=TagsFilter.FILTER_MODE_ALL)),
    near_wall=entities(bounds=sphere(1.5, 3.0, 0.5, 0.6)),
    box=entities(bounds=Bounds(type=Bounds.TYPE_BOX, points=[Vector3(x=-0.2, y=-0.2, z=0.8),
                                                             Vector3(x=0.2, y=0.2, z=1.2)])),
    around_ball=entities(bounds=hull((-1, -1, 0), (1, -1, 0), (0, 1, 0), (0, 0, 2))),
    past_ball=entities(bounds=hull((-1, -1, -0.1), (1.6, -1, -0.1), (-1, 1.6, -0.1),
                                   (-1, -1, 2.5))),
    line=code(call("get_entities", GetEntities, filters=EntityFilters(
        bounds=hull((0, 0, 0), (1, 0, 0), (2, 0, 0)))))[0],
    bad=code(call("get_entities", GetEntities,
                                          filters=EntityFilters(filter="(")))[0],
    states=[list(states.entities), round(states.states[0].pose.position.z, 3)],
    info=[call("get_entity_info", GetEntityInfo, entity="ball").info.description,
          call("get_entity_info", GetEntityInfo, entity="wall").info.category.category])
""")
    assert seen["tagged"] == [1, ""]
    assert seen["pattern"] == ["wall"] and seen["static"] == ["wall"]
    assert seen["robots"] == ["ball"] and seen["any_tag"] == ["ball"] and seen["all_tags"] == []
    assert seen["near_wall"] == ["wall"] and seen["box"] == ["ball"]
    assert seen["around_ball"] == ["ball"]  # a tetrahedron round the ball; the wall is out
    assert seen["past_ball"] == []  # its box holds the ball's, but its slanted face is short
    assert seen["line"] == 4 and seen["bad"] == 4  # OPERATION_FAILED: no hull; a bad pattern
    assert seen["states"] == [["ball"], 1.0]
    assert seen["info"] == ["a ball", 5]


def test_set_entity_state_moves_and_pushes_a_body(arena):
    seen = client(arena, """
target = EntityState()
target.pose.position.x, target.pose.position.z = 3.0, 2.0
target.pose.orientation.w = 1.0
target.twist.linear.x = 1.5
answer = code(call("set_entity_state", SetEntityState, entity="ball", state=target,
                   set_pose=True, set_twist=True))
now = entity_state("ball")
out(answer=answer, at=position("ball"), speed=round(now.twist.linear.x, 3))
""")
    assert seen == {"answer": [1, ""], "at": [3.0, 0.0, 2.0], "speed": 1.5}


def test_set_entity_state_on_a_static_body_refuses_a_twist_and_moves_nothing(arena):
    seen = client(arena, """
target = EntityState()
target.pose.position.x = 5.0
target.pose.orientation.w = 1.0
target.twist.angular.z = 1.0
refused = code(call("set_entity_state", SetEntityState, entity="wall", state=target,
                    set_pose=True, set_twist=True))
moved = code(call("set_entity_state", SetEntityState, entity="wall", state=target,
                  set_pose=True))
out(refused=refused, moved=moved, at=position("wall"))
""")
    assert seen["refused"][0] == 4 and "static" in seen["refused"][1]
    assert seen["moved"] == [1, ""] and seen["at"] == [5.0, 0.0, 0.0]


def test_entity_bounds_are_a_box_in_the_canonical_link_frame(arena):
    seen = client(arena, """
bounds = call("get_entity_bounds", GetEntityBounds, entity="wall").bounds
out(type=bounds.type, points=[[round(p.x, 3), round(p.y, 3), round(p.z, 3)]
                              for p in bounds.points])
""")
    assert seen == {"type": 1, "points": [[1.0, 0.1, 0.5], [-1.0, -0.1, -0.5]]}


def test_reset_simulation_scopes(arena):
    seen = client(arena, f"""
spawn("extra", text={CUBE!r}, initial_pose=pose(0.0, 0.0, 5.0))
call("step_simulation", StepSimulation, steps=300)
spawned_only = code(call("reset_simulation", ResetSimulation, scope=ResetSimulation.Request.SCOPE_SPAWNED))
after_spawned = [entities(), seconds()]
time_only = code(call("reset_simulation", ResetSimulation, scope=ResetSimulation.Request.SCOPE_TIME))
after_time = [seconds(), position("ball")[2] < 1.0]
spawn("extra", text={CUBE!r}, initial_pose=pose(0.0, 0.0, 5.0))
everything = code(call("reset_simulation", ResetSimulation))
out(spawned_only=spawned_only, after_spawned=after_spawned, time_only=time_only,
    after_time=after_time, everything=everything,
    after_all=[entities(), seconds(), position("ball"), state()])
""")
    assert seen["spawned_only"] == [1, ""] and seen["after_spawned"] == [["ball", "wall"], 0.3]
    assert seen["after_time"] == [0.0, True]  # the ball stays where it fell
    assert seen["after_all"] == [["ball", "wall"], 0.0, [0.0, 0.0, 1.0], 0]


def test_named_poses_are_the_worlds_frames(arena):
    seen = client(arena, """
poses = call("get_named_poses", GetNamedPoses).poses
dock = poses[0]
out(names=[p.name for p in poses], at=[round(dock.pose.position.x, 3),
    round(dock.pose.position.y, 3), round(dock.pose.orientation.z, 3)],
    bounds=call("get_named_pose_bounds", GetNamedPoseBounds, name="dock").bounds.type,
    unknown=code(call("get_named_pose_bounds", GetNamedPoseBounds, name="dok")))
""")
    assert seen["names"] == ["dock"] and seen["at"] == [1.0, 2.0, 0.707]
    assert seen["bounds"] == 0  # TYPE_EMPTY: unbounded
    assert seen["unknown"][0] == 2 and "did you mean 'dock'" in seen["unknown"][1]


def test_worlds_and_spawnables(arena):
    seen = client(arena, """
current = call("get_current_world", GetCurrentWorld)
available = call("get_available_worlds", GetAvailableWorlds)
spawnables = call("get_spawnables", GetSpawnables).spawnables
out(current=[current.world.name, current.world.world_resource.uri],
    available=[w.name for w in available.worlds],
    spawnables=[[s.entity_resource.uri, s.description] for s in spawnables])
""")
    assert seen["current"] == ["arena", str(arena.root / "arena.sdf")]
    assert "empty" in seen["available"]
    assert seen["spawnables"] == [["model://crate", "A wooden crate"]]


def test_load_world_puts_a_world_in_the_place_of_the_running_one_stopped(arena):
    arena.write("table_top.xml", MJCF_WORLD)
    seen = client(arena, f"""
spawned = spawn("crate_1", uri="model://crate")
set_state(SimulationState.STATE_PLAYING)
loaded = call("load_world", LoadWorld,
              world_resource=Resource(uri="{arena.root / 'table_top.xml'}"))
current = call("get_current_world", GetCurrentWorld)
out(loaded=code(loaded), name=loaded.world.name, current=current.world.name,
    entities=entities(), state=state(), at=seconds("cube"),
    named=[p.name for p in call("get_named_poses", GetNamedPoses).poses],
    spawned=spawn("crate_2", uri="model://crate")[0])
""")
    assert seen["loaded"] == [1, ""] and seen["name"] == seen["current"] == "table_top"
    assert seen["entities"] == ["cube", "table"]  # the arena's, and crate_1, are gone
    assert seen["state"] == 0 and seen["at"] == 0.0  # stopped: paused at time 0
    assert seen["named"] == ["drop_zone"] and seen["spawned"] == 1
    services = arena.run("gz", "service", "-l").stdout  # the sim's own follow its name
    assert "/world/table_top/create" in services and "/world/arena/create" not in services


def test_load_world_takes_a_world_as_a_string(arena):
    seen = client(arena, f"""
loaded = call("load_world", LoadWorld, world_resource=Resource(resource_string={MJCF_WORLD!r}))
current = call("get_current_world", GetCurrentWorld)
out(loaded=code(loaded)[0], entities=entities(),
    string=current.world.world_resource.resource_string == {MJCF_WORLD!r})
""")
    assert seen == {"loaded": 1, "entities": ["cube", "table"], "string": True}


def test_load_world_refusals_leave_the_running_world(arena):
    arena.write("broken.sdf", "<sdf version='1.9'><world name='b'><model name='m'>")
    arena.write("notes.txt", "a world, surely")
    arena.write("meshy.sdf", "<sdf version='1.9'><world name='meshy'><model name='m'><link "
                "name='l'><visual name='v'><geometry><mesh><uri>model://no_such_model/m.stl"
                "</uri></mesh></geometry></visual></link></model></world></sdf>")
    seen = client(arena, f"""
def load(**resource):
    return code(call("load_world", LoadWorld, world_resource=Resource(**resource)))
out(none=load(), missing=load(uri="no_such_world.sdf"),
    text=load(uri="{arena.root / 'notes.txt'}"), broken=load(uri="{arena.root / 'broken.sdf'}"),
    assets=load(uri="{arena.root / 'meshy.sdf'}"),
    current=call("get_current_world", GetCurrentWorld).world.name, entities=entities())
""")
    assert seen["none"][0] == 102  # NO_RESOURCE
    assert seen["missing"][0] == 2 and "world 'no_such_world.sdf' not found" in \
        seen["missing"][1]
    assert seen["text"][0] == 101 and "expected SDF (<sdf>) or MJCF" in seen["text"][1]
    assert seen["broken"][0] == 103 and "broken.sdf" in seen["broken"][1]
    assert seen["assets"][0] == 104 and "no_such_model" in seen["assets"][1]
    assert seen["current"] == "arena" and seen["entities"] == ["ball", "wall"]


def test_unload_world_leaves_no_world_until_one_is_loaded(arena):
    seen = client(arena, """
unloaded = code(call("unload_world", UnloadWorld))
out(unloaded=unloaded, again=code(call("unload_world", UnloadWorld))[0],
    current=code(call("get_current_world", GetCurrentWorld))[0], state=state(),
    entities=entities(), play=set_state(SimulationState.STATE_PLAYING)[0],
    spawn=spawn("crate_1", uri="model://crate")[:2],
    step=code(call("step_simulation", StepSimulation, steps=5))[0],
    loaded=code(call("load_world", LoadWorld, world_resource=Resource(uri="empty.sdf")))[0],
    after=state())
""")
    assert seen["unloaded"] == [1, ""] and seen["again"] == 101  # NO_WORLD_LOADED
    assert seen["current"] == 101 and seen["state"] == 4  # STATE_NO_WORLD
    assert seen["entities"] == [] and seen["play"] == 103  # INCORRECT_TRANSITION
    assert seen["spawn"][0] == 4 and "no world is loaded" in seen["spawn"][1]
    assert seen["step"] == 4 and (seen["loaded"], seen["after"]) == (1, 0)


def test_quitting_ends_the_sim(ws):
    ws.own_bus()
    proc = ws.start("sim", "-v", "3", output="sim.out")
    ws.wait_for_output("world 'empty'", 60, "sim.out")
    seen = client(ws, "out(answer=set_state(SimulationState.STATE_QUITTING))\n")
    assert seen["answer"] == [1, ""]
    assert proc.wait(30) == 0


def test_an_mjcf_world_has_the_same_api(ws):
    ws.own_bus()
    ws.write("table.xml", MJCF_WORLD)
    proc = ws.start("sim", "-v", "3", "table.xml", output="sim.out")
    try:
        ws.wait_for_output("world 'table_top'", 60, "sim.out")
        seen = client(ws, f"""
cube = spawn("cube2", text={CUBE!r}, initial_pose=pose(0.3, 0.0, 1.2))
call("step_simulation", StepSimulation, steps=10)
out(listed=entities(), named=[p.name for p in call("get_named_poses", GetNamedPoses).poses],
    cube=position("cube"), spawned=cube[0], world=call("get_current_world",
                                                        GetCurrentWorld).world.name)
""")
    finally:
        stop(proc)
    assert seen["listed"] == ["cube", "cube2", "table"]
    assert seen["named"] == ["drop_zone"] and seen["spawned"] == 1
    assert seen["cube"][2] < 0.9 and seen["world"] == "table_top"


RANGER = """<sdf version="1.9"><model name="ranger"><link name="base"><inertial><mass>1</mass>
<inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
<collision name="c"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>
<sensor name="sonar" type="ray"><update_rate>10</update_rate><ray><scan><horizontal>
<samples>1</samples><min_angle>0</min_angle><max_angle>0</max_angle></horizontal></scan>
<range><min>0.05</min><max>5</max></range></ray>
<plugin name="sonar_plugin" filename="libgazebo_ros_ray_sensor.so">
<output_type>sensor_msgs/Range</output_type><ros><namespace>front</namespace></ros></plugin>
</sensor></link></model></sdf>"""


def test_an_entity_namespace_puts_its_ros_interfaces_under_it(arena):
    seen = client(arena, f"""
out(answer=spawn("r7", text={RANGER!r}, entity_namespace="robot7",
                 initial_pose=pose(0.0, -2.0, 0.2)),
    refused=spawn("r8", text={RANGER!r}, entity_namespace="bad name!")[:2])
""")
    assert seen["answer"][:2] == [1, ""], seen
    assert seen["refused"][0] == 105  # NAMESPACE_INVALID
    topics = arena.run("topic", "list", timeout=30).stdout.split()
    assert "/robot7/front/sonar_plugin/out" in topics, topics
