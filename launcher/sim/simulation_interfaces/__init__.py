"""ROS's standard simulator API (ros-simulation/simulation_interfaces 2.1) on the ROS graph,
served by the sim itself (SDF or MJCF world alike) under the names ros_gz gives it: node
`gzserver`, services `/gzserver/<name>` and the action `/gzserver/simulate_steps`.

It is a third face of the sim's own entity operations (world.py, placement.py, the server's
pausing, stepping and resetting), beside the `/world/<w>/…` services and the `/gazebo/*` API:
  simulation.py  GetSimulationState, SetSimulationState, StepSimulation, SimulateSteps,
                 ResetSimulation
  entities.py    GetEntities, GetEntitiesStates, GetEntityState, SetEntityState,
                 GetEntityInfo, SetEntityInfo, GetEntityBounds (and the entity filters)
  spawning.py    SpawnEntity, SpawnEntities (one recompile for the lot), DeleteEntity,
                 GetSpawnables
  worlds.py      GetCurrentWorld, GetAvailableWorlds, GetNamedPoses, GetNamedPoseBounds
  world_loading.py  LoadWorld (a world in the place of the running one), UnloadWorld
GetSimulatorFeatures lists what is served. Every answer carries a Result: OK, or a code and a
message saying what was wrong; a request never stops the sim (QUITTING aside).
"""

from __future__ import annotations

from typing import Any

from launcher.bus.node import Node
from launcher.sim.simulation_interfaces import entities, simulation, spawning, worlds
from launcher.sim.simulation_interfaces.common import TYPES, Api

NODE = "gzserver"

# SimulatorFeatures' values, as this sim serves them
FEATURES = [
    0,   # SPAWNING
    1,   # DELETING
    2,   # NAMED_POSES: the world's top-level sites (MJCF) and frames (SDF)
    3,   # POSE_BOUNDS (each named pose is unbounded)
    4,   # ENTITY_TAGS
    5,   # ENTITY_BOUNDS
    6,   # ENTITY_BOUNDS_BOX (and spheres, which every simulator takes)
    7,   # ENTITY_BOUNDS_CONVEX
    8,   # ENTITY_CATEGORIES
    9,   # SPAWNING_RESOURCE_STRING
    10,  # ENTITY_STATE_GETTING
    11,  # ENTITY_STATE_SETTING
    12,  # ENTITY_INFO_GETTING
    13,  # ENTITY_INFO_SETTING
    14,  # SPAWNABLES
    20, 21, 22, 23,  # SIMULATION_RESET and its TIME, STATE and SPAWNED scopes
    24, 25, 26,  # SIMULATION_STATE_GETTING, _SETTING, _PAUSE
    31, 32, 33,  # STEP_SIMULATION_SINGLE, _MULTIPLE, _ACTION
    40, 41,  # WORLD_LOADING, WORLD_RESOURCE_STRING
    43,  # WORLD_UNLOADING
    44,  # WORLD_INFO_GETTING
    45,  # AVAILABLE_WORLDS
    50,  # SPAWNING_ENTITIES
]
SPAWN_FORMATS = ["sdf", "urdf", "mjcf"]


def serve(server: Any) -> Api:
    """Serve the standard API for the world of `server` (the sim's loop, sim/runner.py), on a
    node of the sim's process that the loop spins."""
    node = Node(NODE, argv=[], session=server.node.session)
    node.spin_with(server.node)
    api = Api(node, server)
    node.create_service(f"{TYPES}/srv/GetSimulatorFeatures", "~/get_simulator_features",
                        on_features)
    simulation.serve(api)
    spawning.serve(api, entities.serve(api))
    worlds.serve(api)
    return api


def on_features(request: Any, response: Any) -> Any:
    response.features.features = list(FEATURES)
    response.features.spawn_formats = list(SPAWN_FORMATS)
    response.features.custom_info = (
        "launcher's MuJoCo sim: entities are the world's models and those spawned; "
        "SpawnEntity takes SDF, URDF and MJCF by path, model://, package:// or file:// URI or "
        "as a string; LoadWorld takes SDF and MJCF worlds the same ways")
    return response
