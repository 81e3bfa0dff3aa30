"""Worlds and named poses through the standard API: GetCurrentWorld (its name and file),
GetAvailableWorlds (the world files of the resource path, of the folders a request names and
the built-in ones), GetNamedPoses and GetNamedPoseBounds (the world's top-level sites: an MJCF
`<site>` in `<worldbody>`, an SDF world's `<frame>`; each unbounded). LoadWorld and
UnloadWorld are world_loading.py's.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from launcher.bus.service_table import create_services
from launcher.errors import did_you_mean
from launcher.sim.resources import BUILTIN_WORLDS, builtin_worlds, resource_entries
from launcher.sim.simulation_interfaces.common import (
    FEATURE_UNSUPPORTED,
    NOT_FOUND,
    OK,
    TYPES,
    Api,
    fill_pose,
    result,
)
from launcher.sim.simulation_interfaces.world_loading import NO_WORLD_LOADED, WorldLoading
from launcher.sim.transform import Pose

WORLD_FILES = (".sdf", ".world")


class Worlds:
    def __init__(self, api: Api, loading: WorldLoading) -> None:
        self.api, self.loading = api, loading
        create_services(api.node, TYPES, (
            ("get_current_world", "GetCurrentWorld", self.on_current),
            ("get_available_worlds", "GetAvailableWorlds", self.on_available),
            ("get_named_poses", "GetNamedPoses", self.on_named_poses),
            ("get_named_pose_bounds", "GetNamedPoseBounds", self.on_named_pose_bounds)))

    def on_current(self, request: Any, response: Any) -> Any:
        if self.api.server.no_world:
            return result(response, NO_WORLD_LOADED, "no world is loaded")
        world = self.api.world
        response.world.name = world.world_name
        if self.loading.resource_string:  # (a world given as a string has no file)
            response.world.world_resource.resource_string = self.loading.resource_string
        else:
            response.world.world_resource.uri = str(world.label)
        return result(response, OK)

    def on_available(self, request: Any, response: Any) -> Any:
        if list(request.filter.tags):
            return result(response, FEATURE_UNSUPPORTED, "worlds have no tags here "
                                                         "(WORLD_TAGS): ask without a filter")
        folders = [folder for folder, _ in resource_entries(self.api.world.templates.environ)]
        unknown = []
        for source in request.additional_sources:
            folder = Path(source[len("file://"):] if source.startswith("file://") else source)
            if folder.is_dir():
                folders.append(folder)
            else:
                unknown.append(source)
        found = []
        for folder in folders:
            for path in sorted(folder.iterdir()) if folder.is_dir() else ():
                if path.is_file() and (path.suffix in WORLD_FILES or _is_mjcf(path)):
                    found.append(self._world(path.stem, str(path)))
        for name in builtin_worlds():
            found.append(self._world(name.split(".")[0], str(BUILTIN_WORLDS / name),
                                     "built into launcher"))
        response.worlds = found
        if unknown and not request.continue_on_error and not found:
            return result(response, NOT_FOUND, f"sources not found: {', '.join(unknown)}")
        return result(response, OK, f"sources not found, left out: {', '.join(unknown)}"
                      if unknown else "")

    def _world(self, name: str, uri: str, description: str = "") -> Any:
        world = self.api.node.message(f"{TYPES}/msg/WorldResource")
        world.name, world.world_resource.uri, world.description = name, uri, description
        return world

    # --- named poses -------------------------------------------------------------------------
    def named(self) -> dict[str, Pose]:
        model = self.api.world.model
        poses = {}
        for site in range(model.nsite):
            if model.site_bodyid[site] == 0 and model.site(site).name:
                poses[model.site(site).name] = Pose(tuple(model.site_pos[site].tolist()),
                                                    tuple(model.site_quat[site].tolist()))
        return poses

    def on_named_poses(self, request: Any, response: Any) -> Any:
        if list(request.tags.tags):  # named poses carry no tags: none matches
            response.poses = []
            return result(response, OK)
        found = []
        for name, pose in self.named().items():
            named = self.api.node.message(f"{TYPES}/msg/NamedPose", name=name)
            fill_pose(named.pose, pose)
            found.append(named)
        response.poses = found
        return result(response, OK)

    def on_named_pose_bounds(self, request: Any, response: Any) -> Any:
        named = self.named()
        if request.name not in named:
            return result(response, NOT_FOUND, f"no named pose '{request.name}'"
                          f"{did_you_mean(request.name, list(named))}; the world has: "
                          f"{', '.join(named) or 'none'}")
        response.bounds.type = 0  # TYPE_EMPTY: unbounded
        return result(response, OK)


def _is_mjcf(path: Path) -> bool:
    if path.suffix != ".xml":
        return False
    try:
        with path.open(errors="replace") as file:
            head = file.read(2048)
    except OSError:
        return False
    return "<mujoco" in head


def serve(api: Api) -> Worlds:
    return Worlds(api, WorldLoading(api))
