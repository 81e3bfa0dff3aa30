"""LoadWorld and UnloadWorld through the standard API.

LoadWorld takes a world, SDF or MJCF, by `uri` (a path, `file://`, `package://`, or a name
found as `gz sim NAME` finds it) or as a `resource_string`, and puts it in the place of the
running one (server.load): the old world's entities and plugins go, the new one is stopped
(paused at time 0), and the sim's `/world/<name>/…` services follow its name (a bridge
configured for the old name, as with Gazebo, does not). The world is loaded in full before
anything is replaced, so a request that fails leaves the running world as it was:
NO_RESOURCE (neither field), NOT_FOUND (a uri that resolves nowhere), UNSUPPORTED_FORMAT
(neither `<sdf>` nor `<mujoco>`), RESOURCE_PARSE_ERROR (what the loader refuses, its message
with the file and line), MISSING_ASSETS (a mesh or model it names is nowhere),
UNSUPPORTED_ELEMENTS (with `fail_on_unsupported_element`, what launcher would leave out).
Missing assets are never ignored (`ignore_missing_or_unsupported_assets` does not change that).

UnloadWorld removes the world and its entities: until a world is loaded, the sim holds an empty
stand-in under the old name, GetCurrentWorld answers NO_WORLD_LOADED, the state is
STATE_NO_WORLD, and stepping, playing and spawning are refused.
"""

from __future__ import annotations

import tempfile
from pathlib import Path
from typing import Any

import mujoco

from launcher.errors import LaunchError
from launcher.sim.resources import ResourceNotFound, find_world, resolve_uri
from launcher.sim.sdf.xmltree import after_prologue
from launcher.sim.simulation_interfaces.common import NOT_FOUND, OK, TYPES, Api, result
from launcher.sim.simulation_interfaces.entities import Refused
from launcher.sim.world import World
from launcher.user_files import read_text

UNSUPPORTED_FORMAT, NO_RESOURCE, RESOURCE_PARSE_ERROR, MISSING_ASSETS = 101, 102, 103, 104
UNSUPPORTED_ELEMENTS = 106
NO_WORLD_LOADED = 101  # (UnloadWorld's and GetCurrentWorld's)


class WorldLoading:
    def __init__(self, api: Api) -> None:
        self.api = api
        self.resource_string = ""  # the loaded world's, when it came as a string
        node = api.node
        node.create_service(f"{TYPES}/srv/LoadWorld", "~/load_world", self.on_load)
        node.create_service(f"{TYPES}/srv/UnloadWorld", "~/unload_world", self.on_unload)

    def on_load(self, request: Any, response: Any) -> Any:
        resource = request.world_resource
        server = self.api.server
        try:
            world = self._world(resource.uri.strip(), resource.resource_string,
                                bool(request.fail_on_unsupported_element))
        except Refused as exc:
            return result(response, *exc.args)
        server.load(world)
        self.resource_string = "" if resource.uri.strip() else resource.resource_string
        self.api.node.get_logger().info(f"LoadWorld: world '{world.world_name}' from "
                                        f"{world.label} (stopped)")
        response.world.name = world.world_name
        response.world.world_resource.uri = resource.uri.strip() and str(world.label)
        response.world.world_resource.resource_string = self.resource_string
        return result(response, OK)

    def _world(self, uri: str, text: str, strict: bool) -> World:
        if not uri and not text.strip():
            raise Refused(NO_RESOURCE, "give the world as world_resource.uri or as "
                                       "world_resource.resource_string")
        if uri:
            return self._from_path(self._path(uri), strict)
        suffix = _suffix(text, "the resource_string")
        with tempfile.TemporaryDirectory(prefix="world_") as folder:  # (private, 0700)
            path = Path(folder) / f"world{suffix}"
            path.write_text(text)
            return self._from_path(path, strict)

    def _path(self, uri: str) -> Path:
        environ = self.api.world.templates.environ
        try:
            if uri.startswith(("package://", "file://", "model://")):
                return resolve_uri(uri, None, environ=environ)
            return find_world(uri, environ)
        except LaunchError as exc:
            raise Refused(NOT_FOUND, str(exc)) from None

    def _from_path(self, path: Path, strict: bool) -> World:
        try:
            _suffix(read_text(path), str(path))
            world = World.from_path(path, self.api.server.transport,
                                    environ=self.api.world.templates.environ,
                                    seed=self.api.world.seed)
        except ResourceNotFound as exc:
            raise Refused(MISSING_ASSETS, str(exc)) from None
        except LaunchError as exc:
            raise Refused(RESOURCE_PARSE_ERROR, str(exc)) from None
        if strict and world.load_warnings:
            world.close()
            raise Refused(UNSUPPORTED_ELEMENTS, "; ".join(world.load_warnings))
        return world

    def on_unload(self, request: Any, response: Any) -> Any:
        server = self.api.server
        if server.no_world:
            return result(response, NO_WORLD_LOADED, "no world is loaded")
        name = server.world.world_name
        stand_in = mujoco.MjSpec.from_string(f'<mujoco model="{name}"/>')
        server.load(World(stand_in, "no world", server.transport,
                          templates=server.world.templates), no_world=True)
        self.resource_string = ""
        self.api.node.get_logger().info(f"UnloadWorld: world '{name}' and its entities "
                                        "removed")
        return result(response, OK)


def _suffix(text: str, what: str) -> str:
    head = after_prologue(text)
    if head.startswith("<sdf"):
        return ".sdf"
    if head.startswith("<mujoco"):
        return ".xml"
    raise Refused(UNSUPPORTED_FORMAT, f"{what}: not a world launcher loads: expected SDF "
                                      f"(<sdf>) or MJCF (<mujoco>), found '{head[:40]}'")
