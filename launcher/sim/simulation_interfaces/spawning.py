"""Adding and removing entities through the standard API: SpawnEntity, SpawnEntities,
DeleteEntity and GetSpawnables.

A spawn reads its resource (a path, `file://`, `model://` or `package://` URI, or the
description itself as a string: SDF, URDF or MJCF) and joins the sim's batch of spawns: the
requests that arrive together, these and `create`'s, are added with one recompile
(world.spawn_all). Each is answered once it is in the world, or with the SpawnResult code that
says why not. An empty name takes the description's; an all-zero pose in the world frame
keeps the description's own pose, as `create` does. The spawnables are the model folders of
the resource path (and of the folders a request names), as `model://` URIs.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

from launcher.bus.names import InvalidName, check_namespace
from launcher.bus.service_table import create_services
from launcher.errors import LaunchError
from launcher.sim.entity import NameInvalid, NameTaken, Spawn, SpawnError
from launcher.sim.resources import ResourceNotFound, resolve_uri, resource_dirs
from launcher.sim.simulation_interfaces.common import (
    NO_WORLD_TEXT,
    NOT_FOUND,
    OK,
    OPERATION_FAILED,
    TYPES,
    Api,
    pose_of,
    result,
)
from launcher.sim.simulation_interfaces.entities import Entities, Refused, answering
from launcher.sim.templates import UnsupportedFormat
from launcher.sim.transform import IDENTITY

NAME_NOT_UNIQUE, NAME_INVALID, UNSUPPORTED_FORMAT, NO_RESOURCE = 101, 102, 103, 104
NAMESPACE_INVALID, RESOURCE_PARSE_ERROR, MISSING_ASSETS, INVALID_POSE = 105, 106, 107, 109
ENTITIES_SPAWN_FAILED = 150


class Spawning:
    def __init__(self, api: Api, entities: Entities) -> None:
        self.api, self.entities = api, entities
        for service in create_services(api.node, TYPES, (
                ("spawn_entity", "SpawnEntity", self.on_spawn),
                ("spawn_entities", "SpawnEntities", self.on_spawn_all))):
            service.deferred = True
        create_services(api.node, TYPES, (
            ("delete_entity", "DeleteEntity", self.on_delete),
            ("get_spawnables", "GetSpawnables", self.on_spawnables)))

    # --- spawning ----------------------------------------------------------------------------
    def request(self, asked: Any) -> Spawn:
        """The sim's spawn request for a SpawnEntity request (Refused: code and reason)."""
        world = self.api.world
        if self.api.server.no_world:
            raise Refused(OPERATION_FAILED, NO_WORLD_TEXT)
        resource = asked.entity_resource
        uri, text = resource.uri.strip(), resource.resource_string
        try:
            namespace = asked.entity_namespace.strip()
            if namespace:
                check_namespace(namespace)
            if uri:
                try:
                    path = resolve_uri(uri, None, world.templates.packages,
                                       world.templates.environ)
                except ResourceNotFound as exc:
                    raise Refused(NOT_FOUND, str(exc)) from None
                template = world.templates.from_file(str(path))
            elif text.strip():
                template = world.templates.from_string(text, f"entity '{asked.name}'")
            else:
                raise Refused(NO_RESOURCE, "nothing to spawn: give entity_resource.uri or "
                                           "entity_resource.resource_string")
        except InvalidName as exc:
            raise Refused(NAMESPACE_INVALID, str(exc)) from None
        except UnsupportedFormat as exc:
            raise Refused(UNSUPPORTED_FORMAT, str(exc)) from None
        except ResourceNotFound as exc:
            raise Refused(MISSING_ASSETS, str(exc)) from None
        except LaunchError as exc:
            raise Refused(RESOURCE_PARSE_ERROR, str(exc)) from None
        frame_id = asked.initial_pose.header.frame_id
        frame = self.api.frame(frame_id)
        if frame is None:
            raise Refused(INVALID_POSE, f"initial_pose's frame '{frame_id}' is neither the "
                                        "world nor an entity")
        try:
            pose = pose_of(asked.initial_pose.pose)
        except ValueError as exc:
            raise Refused(INVALID_POSE, str(exc)) from None
        if frame is IDENTITY and pose == IDENTITY:
            pose = template.pose  # none given: the description's own
        pose = frame * pose
        return Spawn(template, asked.name, list(pose.pos), list(pose.quat),
                     asked.allow_renaming, namespace=namespace)

    def spawn(self, asked: Any, answer: Any, done: Any) -> None:
        """Spawn one request; `answer` (a SpawnEntity response or a SpawnResult) is filled
        and handed to `done` once it is in the world or refused."""
        try:
            request = self.request(asked)
        except Refused as refused:
            done(result(answer, *refused.args))
            return

        def spawned(entity: Any) -> None:
            if isinstance(entity, SpawnError):
                code = NAME_NOT_UNIQUE if isinstance(entity, NameTaken) else \
                    NAME_INVALID if isinstance(entity, NameInvalid) else RESOURCE_PARSE_ERROR
                done(result(answer, code, str(entity)))
                return
            answer.entity_name = entity.name
            done(result(answer, OK))

        self.api.server.spawn_soon(request, spawned)

    def on_spawn(self, asked: Any, reply: Any) -> None:
        self.spawn(asked, reply.new_response(), reply.send)

    def on_spawn_all(self, request: Any, reply: Any) -> None:
        response = reply.new_response()
        asked = list(request.spawn_requests)
        answers = [self.api.node.message(f"{TYPES}/msg/SpawnResult") for _ in asked]
        left = [len(asked)]

        def one_done(_: Any) -> None:
            left[0] -= 1
            if left[0] == 0:
                response.results = answers
                failed = sum(a.result.result != OK for a in answers)
                reply.send(result(response, ENTITIES_SPAWN_FAILED,
                                  f"{failed} of {len(answers)} spawns failed: see results")
                           if failed else result(response, OK))

        if not asked:
            reply.send(result(response, OK))
            return
        for one, answer in zip(asked, answers, strict=True):
            self.spawn(one, answer, one_done)

    # --- deleting ----------------------------------------------------------------------------
    @answering
    def on_delete(self, request: Any, response: Any) -> Any:
        self.entities.entity(request.entity)
        self.api.world.remove(request.entity)
        self.api.node.get_logger().info(f"removed '{request.entity}'")
        self.api.server.publish_clock()
        return result(response, OK)

    # --- spawnables --------------------------------------------------------------------------
    def on_spawnables(self, request: Any, response: Any) -> Any:
        folders = list(resource_dirs(self.api.world.templates.environ))
        unknown = []
        for source in request.sources:
            folder = Path(source[len("file://"):] if source.startswith("file://") else source)
            (folders if folder.is_dir() else unknown).append(folder if folder.is_dir()
                                                             else source)
        found, seen = [], set()
        for folder in folders:
            for model in sorted(folder.iterdir()) if folder.is_dir() else ():
                if (model / "model.config").is_file() and model.name not in seen:
                    seen.add(model.name)
                    found.append(self._spawnable(model))
        response.spawnables = found
        return result(response, OK, f"sources not found, left out: {', '.join(unknown)}"
                      if unknown else "")

    def _spawnable(self, folder: Path) -> Any:
        spawnable = self.api.node.message(f"{TYPES}/msg/Spawnable")
        spawnable.entity_resource.uri = f"model://{folder.name}"
        try:
            description = ET.parse(folder / "model.config").getroot().findtext("description")
        except ET.ParseError:
            description = None
        spawnable.description = " ".join((description or folder.name).split())
        return spawnable


def serve(api: Api, entities: Entities) -> Spawning:
    return Spawning(api, entities)
