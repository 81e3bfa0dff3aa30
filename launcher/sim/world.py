"""The world: one MjSpec, its model and data, and its entities.

Every model of the world file is an entity (an SDF `<model>`; an MJCF top-level body), as is
everything spawned: listed, moved, removed and reset alike. An entity's pose is its model
frame's (its root body's pose times the inverse of `offset`); a static entity has no joint
and is moved by moving its body.

Spawning copies a description's template, gives its root body a free joint, lets its plugins
add actuators, attaches it at a frame with the prefix `<name>/`, and recompiles keeping the
state (qpos, qvel, ctrl, time) of everything already there. A spawn that fails anywhere
leaves the world as it was. Recompiling makes new model and data objects: everything bound to
them is re-bound after it.

The world's parts, each in its module: `plugins` (plugin_host.py: the world's and the
entities' plugins), `physics` (stepping.py: stepping in batches), `placement` (placement.py:
poses and velocities). It talks to the bus only through `transport` (publisher / subscribe /
message / logger), so it can be stepped without one.
"""

from __future__ import annotations

import contextlib
import dataclasses
import hashlib
import math
import re
import struct
from collections.abc import Collection, Mapping, Sequence
from pathlib import Path
from typing import Any

import mujoco

from launcher.errors import LaunchError, Location, did_you_mean
from launcher.sim.entity import Entity, NameInvalid, NameTaken, Spawn, SpawnError
from launcher.sim.loading import WorldModel, load_world_file
from launcher.sim.mjcf import PluginConfig
from launcher.sim.placement import Placement, checked
from launcher.sim.plugin_host import PluginHost
from launcher.sim.plugins import systems_of
from launcher.sim.sdf.geometry import friction_priority
from launcher.sim.sensors.geodesy import SphericalCoordinates
from launcher.sim.stepping import Physics
from launcher.sim.templates import Template, Templates
from launcher.sim.transform import Pose, pose_from
from launcher.sim.transport import Transport
from launcher.user_files import read_text

__all__ = ["Entity", "Spawn", "SpawnError", "World", "world_name"]

_NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")


def world_name(name: str) -> str:
    """The name in `/world/<name>/…`: the MJCF model's or the SDF world's, made a valid name
    part; MuJoCo's own default ("MuJoCo Model", an MJCF without `model=`) is Gazebo's
    "default"."""
    if not name or name == "MuJoCo Model":
        return "default"
    name = re.sub(r"\W", "_", name, flags=re.ASCII)
    return f"_{name}" if name[0].isdigit() else name


class World:
    real_time_factor: float | None = None  # the world file's own pace, if it sets one
    keyframe: str = ""  # the MJCF keyframe the world starts from and resets to (start_from)

    @classmethod
    def from_path(cls, path: Path, transport: Transport, values: Mapping[str, str] | None = None,
                  environ: Mapping[str, str] | None = None, seed: int = 0,
                  as_written: bool = False) -> World:
        """The world of an SDF or MJCF file (a `.j2` rendered with `values`); what the file
        holds that launcher leaves out is logged, once each. `as_written`: an MJCF with
        MuJoCo's own defaults."""
        loaded = load_world_file(path, values, environ, as_written)
        for warning in loaded.warnings:
            transport.logger.warning(warning)
        world = cls(loaded.spec, loaded.label, transport, loaded.plugins, models=loaded.models,
                    seed=seed, spherical_coordinates=loaded.spherical_coordinates)
        world.real_time_factor = loaded.real_time_factor
        world.load_warnings = list(loaded.warnings)
        return world

    def __init__(self, spec: mujoco.MjSpec, label: str, transport: Transport,
                 plugins: Sequence[PluginConfig] = (),
                 templates: Templates | None = None,
                 models: Sequence[WorldModel] | None = None, seed: int = 0,
                 spherical_coordinates: Any = None) -> None:
        """`models`: the world file's models (SDF); None takes MJCF's top-level bodies.
        `seed` seeds the sensors' noise."""
        self.spec, self.label, self.transport = spec, label, transport
        self.load_warnings: list[str] = []  # what the file holds that launcher leaves out
        self.world_name = world_name(spec.modelname)
        if self.world_name not in (spec.modelname, "default"):
            transport.logger.warning(f"world name '{spec.modelname}' is not a valid ROS name "
                                     f"part; its topics use '{self.world_name}'")
        self.templates = templates or Templates()
        self.seed = seed
        self.spherical_coordinates = spherical_coordinates or SphericalCoordinates()
        # the world systems its sensors need (an MJCF world declares none: all of them run)
        self.systems = None if models is None else systems_of(plugins)
        self.entities: dict[str, Entity] = {}
        self.plugins = PluginHost(self, transport.logger,
                                  lambda: (e.plugins for e in self.entities.values()))
        self.physics = Physics(self.plugins, transport.logger)
        self.placement = Placement(self)
        self._plugin_configs = list(plugins)
        self._warned: set[str] = set()
        for model in models if models is not None else _top_level_models(spec):
            self._add_world_model(model)
        self.model = _compile(spec, label)
        self.data = mujoco.MjData(self.model)
        self.plugins.changed()
        self._rebind(self.model, self.data)
        for entity in list(self.entities.values()):
            self.plugins.load(entity.plugins)

    def _add_world_model(self, model: WorldModel) -> None:
        anchors = [self.spec.body(root) for root in model.roots]
        entity = Entity(model.name, anchors, model.root, self.label, offset=model.offset,
                        roots=list(model.roots), static=model.static)
        entity.plugins = [p for p in (self.plugins.make(c, entity) for c in model.plugins) if p]
        for plugin in list(entity.plugins):
            plugin.spec_prefix = f"{model.name}/"
            try:
                plugin.prepare(self.spec)
            except Exception as exc:  # a plugin's bug or bad config: the world still loads
                message = f"{exc}; {plugin.label} of entity '{model.name}' is left out" \
                    if isinstance(exc, LaunchError) else \
                    f"plugin {plugin.label}: {type(exc).__name__}: {exc}; entity " \
                    f"'{model.name}' runs without it"
                self.transport.logger.error(message)
                entity.plugins.remove(plugin)
        self.entities[model.name] = entity

    def load_world_plugins(self, before: Sequence[PluginConfig] = ()) -> None:
        """Load `before` (the sim's own) and the world file's plugins; one that fails is
        logged and left out."""
        self.plugins.load_world_plugins([*before, *self._plugin_configs], self.model,
                                        self.data)

    # --- entities --------------------------------------------------------------------------
    def unique_name(self, name: str, allow_renaming: bool,
                    taken: Collection[str] = ()) -> str:
        """`name`, or with allow_renaming the first free `name_N`; `taken`: names given to
        entities not yet added (the same batch of spawns)."""
        if not _NAME.match(name):
            raise NameInvalid(f"invalid entity name '{name}': use letters, digits and '_' "
                              "(it prefixes every body, joint and topic of the entity)")

        def free(candidate: str) -> bool:
            return candidate not in self.entities and candidate not in taken and \
                not self._name_in_model(candidate)

        if free(name):
            return name
        if not allow_renaming:
            raise NameTaken(f"an entity named '{name}' already exists; choose another name or "
                            "set allow_renaming")
        number = 1
        while not free(f"{name}_{number}"):
            number += 1
        return f"{name}_{number}"

    def _name_in_model(self, name: str) -> bool:
        prefix = f"{name}/"
        return any(b.name.startswith(prefix) or b.name == name for b in self.spec.bodies)

    def spawn(self, template: Template, name: str, position: Sequence[float],
              quat: Sequence[float], allow_renaming: bool = False,
              joints: Mapping[str, float] | None = None, keyframe: str = "") -> Entity:
        """Add the template as entity `name`; `joints` gives hinge and slide joints their first
        positions (a reset puts them back at zero, as the model has them); `keyframe`, an MJCF
        description's `<key>`, gives its joints theirs (and resets return to it)."""
        done = self.spawn_all([Spawn(template, name, position, quat, allow_renaming, joints,
                                     keyframe)])[0]
        if isinstance(done, SpawnError):
            raise done
        return done

    def spawn_all(self, requests: Sequence[Spawn]) -> list[Entity | SpawnError]:
        """Add several entities with one recompile (each recompile is of the whole model, so
        ten spawns at once cost about one); each request succeeds or fails alone, and one that
        fails leaves the world as it was. The entity, or the reason, for each request."""
        results: list[Entity | SpawnError] = []
        ready: list[tuple[int, Entity, mujoco.MjSpec, Spawn]] = []
        taken: set[str] = set()
        for request in requests:
            try:
                entity, child = self._prepare(request, taken)
            except SpawnError as exc:
                results.append(exc)
                continue
            taken.add(entity.name)
            ready.append((len(results), entity, child, request))
            results.append(entity)
        if not ready:
            return results
        frames = []
        try:
            for _, entity, child, request in ready:
                frames.append(self.spec.worldbody.add_frame(pos=list(request.position),
                                                            quat=list(request.quat)))
                self.spec.attach(child, frame=frames[-1], prefix=f"{entity.name}/")
            self.spec.dedup_assets()  # ten copies of a robot share its meshes
            self.model, self.data = self.spec.recompile(self.model, self.data)
        except Exception as exc:
            for frame in frames:
                self.spec.delete(frame)
            if len(ready) > 1:  # find the one that breaks it: each alone
                for index, _, _, request in ready:
                    results[index] = self.spawn_all([request])[0]
                return results
            index, entity, _, request = ready[0]
            results[index] = SpawnError(f"{request.template.label}: MuJoCo could not add "
                                        f"'{entity.name}': {' '.join(str(exc).split())}")
            return results
        for frame, (_, entity, _, _) in zip(frames, ready, strict=True):
            entity.anchors = [frame]
            self.entities[entity.name] = entity
        self.plugins.changed()
        self._rebind(self.model, self.data)
        placed = False
        for _, entity, _, request in ready:
            placed = self._put_at_start(entity) or placed
            for joint, value in (request.joints or {}).items():
                index = self.model.joint(f"{entity.name}/{joint}").id
                self.data.qpos[self.model.jnt_qposadr[index]] = value
                placed = True
        if placed:
            mujoco.mj_forward(self.model, self.data)
        for _, entity, _, _ in ready:
            self.plugins.load(entity.plugins)
        return results

    def _prepare(self, request: Spawn, taken: set[str]) -> tuple[Entity, mujoco.MjSpec]:
        """The entity a request makes (not yet in the world) and the spec to attach."""
        template = request.template
        checked(request.position, request.quat)
        name = self.unique_name(request.name or template.name, request.allow_renaming, taken)
        for warning in template.warnings:
            if warning not in self._warned:
                self._warned.add(warning)
                self.transport.logger.warning(warning)
        child, roots = _child_of(template, request.joints or {})
        root = template.root or roots[0].name
        entity = Entity(name, [], f"{name}/{root}", template.label, offset=template.offset,
                        roots=[f"{name}/{body.name}" for body in roots], spawned=True,
                        static=template.static and _jointless(child.worldbody))
        configs = [dataclasses.replace(c, namespace=request.namespace) for c in template.plugins] \
            if request.namespace else template.plugins
        plugins = [p for p in (self.plugins.make(c, entity) for c in configs) if p]
        for plugin in plugins:
            try:
                plugin.prepare(child)
            except LaunchError as exc:
                raise SpawnError(str(exc)) from None
        entity.plugins = plugins
        if request.keyframe:
            entity.start = {f"{name}/{joint}": values for joint, values in
                            _key_joints(template, request.keyframe).items()}
        return entity, child

    def _put_at_start(self, entity: Entity) -> bool:
        """Put a robot spawned from a keyframe back at it (after a spawn or a reset)."""
        for joint, values in entity.start.items():
            address = self.model.jnt_qposadr[self.model.joint(joint).id]
            self.data.qpos[address:address + len(values)] = values
        return bool(entity.start)

    def spawn_file(self, uri: str, name: str, pose: Sequence[float] = (0, 0, 0, 0, 0, 0),
                   allow_renaming: bool = False) -> Entity:
        """Spawn from a file or `model://`/`package://` URI at (x, y, z, roll, pitch, yaw)."""
        position, quat = pose_from(list(pose))
        return self.spawn(self.templates.from_file(uri), name, position, quat,
                          allow_renaming)

    def remove(self, name: str) -> None:
        self.remove_all([name])

    def remove_all(self, names: Sequence[str]) -> None:
        """Remove these entities with one recompile (an unknown name: SpawnError, nothing
        removed)."""
        entities = [self.entity(name) for name in names]
        if not entities:
            return
        for entity in entities:
            for anchor in entity.anchors:
                self.spec.delete(anchor)
        model, data = self.spec.recompile(self.model, self.data)
        for entity in entities:
            del self.entities[entity.name]
        self.plugins.changed()
        for entity in entities:
            for plugin in entity.plugins:
                plugin.close()
        self._rebind(model, data)

    def close(self) -> None:
        """The world is done with (another takes its place): every plugin closed, its
        renderer stopped."""
        for plugin in list(self.plugins.all):
            with contextlib.suppress(Exception):  # (one that fails must not keep the rest)
                plugin.close()
        rendering = getattr(self, "rendering", None)
        if rendering is not None:
            rendering.retire()

    def state_digest(self) -> str:
        """The first 16 hex digits of a sha256 over the sim time and what MuJoCo steps (qpos,
        qvel, act): the same world, seed and commands give the same digest at the same time,
        on machines of the same architecture and versions."""
        digest = hashlib.sha256(struct.pack("<d", self.data.time))
        for values in (self.data.qpos, self.data.qvel, self.data.act):
            digest.update(values.tobytes())
        return digest.hexdigest()[:16]

    def entity(self, name: str) -> Entity:
        if name not in self.entities:
            raise SpawnError(f"no entity named '{name}'"
                             f"{did_you_mean(name, list(self.entities))}")
        return self.entities[name]

    def _rebind(self, model: Any, data: Any) -> None:
        self.model, self.data = model, data
        self.physics.bind(model, data)
        for entity in self.entities.values():
            entity.body = model.body(entity.root).id
            joint = int(model.body_jntadr[entity.body])
            free = joint >= 0 and model.jnt_type[joint] == mujoco.mjtJoint.mjJNT_FREE
            entity.qpos = int(model.jnt_qposadr[joint]) if free else -1
            entity.dof = int(model.jnt_dofadr[joint]) if free else -1
            for root in entity.roots:
                body = model.body(root).id
                if root not in entity.placed and model.body_jntnum[body] == 0:
                    entity.placed[root] = Pose(tuple(model.body_pos[body].tolist()),
                                               tuple(model.body_quat[body].tolist()))
        mujoco.mj_forward(model, data)
        self.plugins.bind(model, data)

    # --- resets ----------------------------------------------------------------------------
    def start_from(self, keyframe: str) -> None:
        """Start, and from now on reset, at the MJCF keyframe named `keyframe` (`<key>`);
        entities spawned later keep their own start in it. A name the model lacks is an
        error naming the nearest ones."""
        names = [self.model.key(i).name for i in range(self.model.nkey)]
        if keyframe not in names:
            raise LaunchError(f"no keyframe '{keyframe}' in the world"
                              f"{did_you_mean(keyframe, names)}; its keyframes: "
                              f"{', '.join(names) or 'none (an MJCF <keyframe><key name=…>)'}",
                              Location(self.label))
        self.keyframe = keyframe
        self.reset()

    def reset(self, time: bool = True, poses: bool = True) -> None:
        """Reset all (both), time only, or poses only (Gazebo's WorldReset); poses go back to
        the world's keyframe when it starts from one."""
        key = self.model.key(self.keyframe) if self.keyframe else None
        if time and poses:
            mujoco.mj_resetData(self.model, self.data)
            if key is not None:
                mujoco.mj_resetDataKeyframe(self.model, self.data, key.id)
        elif poses:
            self.data.qpos[:] = self.model.qpos0 if key is None else key.qpos
            self.data.qvel[:] = 0.0 if key is None else key.qvel
            self.data.act[:] = 0.0 if key is None else key.act
            self.data.ctrl[:] = 0.0 if key is None else key.ctrl
        if poses:
            for entity in self.entities.values():  # static entities that were moved
                for root, pose in entity.placed.items():
                    self.placement.put_static(self.model.body(root).id, pose)
                self._put_at_start(entity)
        if time:
            self.data.time = 0.0
            self.physics.iterations = 0
        mujoco.mj_forward(self.model, self.data)
        self.plugins.reset()


def _key_joints(template: Template, keyframe: str) -> dict[str, list[float]]:
    """The joints of an MJCF description's keyframe and their positions in it; the free
    joints of its root bodies are left out (the spawn pose places those)."""
    model = template.spec.copy().compile()
    names = [model.key(i).name for i in range(model.nkey)]
    if keyframe not in names:
        raise SpawnError(f"{template.label}: no keyframe '{keyframe}' in the description"
                         f"{did_you_mean(keyframe, names)}; its keyframes: "
                         f"{', '.join(names) or 'none (an MJCF <keyframe><key name=…>)'}")
    qpos = model.key(keyframe).qpos
    found = {}
    for joint in range(model.njnt):
        body = int(model.jnt_bodyid[joint])
        if not model.joint(joint).name or (model.jnt_type[joint] == mujoco.mjtJoint.mjJNT_FREE
                                           and int(model.body_parentid[body]) == 0):
            continue  # (an unnamed joint cannot be found again once attached)
        start = int(model.jnt_qposadr[joint])
        width = {int(mujoco.mjtJoint.mjJNT_FREE): 7, int(mujoco.mjtJoint.mjJNT_BALL): 4}.get(
            int(model.jnt_type[joint]), 1)
        found[model.joint(joint).name] = qpos[start:start + width].tolist()
    return found


def _child_of(template: Template, joints: Mapping[str, float]) -> tuple[mujoco.MjSpec, list]:
    """A copy of the template's spec to attach, and its root bodies: free joints at the roots
    (unless static), the links' friction, the joints to place checked."""
    child = template.spec.copy()
    roots = list(child.worldbody.bodies)
    if not roots:
        raise SpawnError(f"{template.label}: the description has no body")
    for body in roots if not template.static else ():
        if not list(body.joints):
            body.add_freejoint()
    for link, mu in template.friction.items():
        body = child.body(link)
        if body is not None:
            for geom in body.geoms:
                geom.friction[0] = mu
    for geom in child.geoms:  # a contact takes the lower friction, as in Gazebo
        if (geom.contype or geom.conaffinity) and not geom.priority:
            geom.priority = friction_priority(float(geom.friction[0]))
    _check_joints(child, joints, template.label)
    return child, roots


def _check_joints(spec: mujoco.MjSpec, joints: Mapping[str, float], label: str) -> None:
    """Each named joint is a hinge or slide of the model, each position a finite number."""
    kinds = {j.name: j.type for j in spec.joints if j.name}
    for joint, value in joints.items():
        if joint not in kinds:
            raise SpawnError(f"{label}: no joint named '{joint}'{did_you_mean(joint, kinds)}; "
                             f"its joints: {', '.join(sorted(kinds)) or 'none'}")
        if kinds[joint] not in (mujoco.mjtJoint.mjJNT_HINGE, mujoco.mjtJoint.mjJNT_SLIDE):
            raise SpawnError(f"{label}: joint '{joint}' is not a revolute, continuous or "
                             "prismatic joint: one position cannot place it")
        if not math.isfinite(value):
            raise SpawnError(f"{label}: joint '{joint}': position {value} is not a finite "
                             "number")


def _top_level_models(spec: mujoco.MjSpec) -> list[WorldModel]:
    """An MJCF world's models: its top-level bodies (static: none of its bodies has a
    joint)."""
    return [WorldModel(body.name, body.name, [body.name], static=_jointless(body))
            for body in spec.worldbody.bodies if body.name]


def _jointless(body: Any) -> bool:
    """Nothing in `body` can move: not one joint in it (a URDF robot anchored to `world`
    has no free joint, but its arm moves)."""
    return not body.find_all(mujoco.mjtObj.mjOBJ_JOINT)


def _compile(spec: mujoco.MjSpec, label: str) -> Any:
    try:
        model = spec.compile()
    except ValueError as exc:
        message = " ".join(str(exc).split())
        raise LaunchError(f"MuJoCo could not compile the world: {message}",
                          locate(label, message)) from None
    if not model.opt.timestep > 0:
        raise LaunchError(f"the timestep must be > 0 s, got {model.opt.timestep:g} (MuJoCo "
                          f"would never advance)", locate(label, "'timestep'")) from None
    return model


def locate(label: str, message: str) -> Location:
    """Where in the file `label` a MuJoCo message points: the line it names, else the first
    place the file holds a name the message quotes (a mesh's file name)."""
    found = re.search(r"\bline (\d+)", message)
    if found:
        return Location(label, int(found.group(1)))
    try:
        text = read_text(label)
    except (OSError, LaunchError, UnicodeDecodeError):
        return Location(label)
    for name in re.findall(r"'([^']+)'", message):
        at = text.find(name)
        if at >= 0:
            line = text.count("\n", 0, at) + 1
            return Location(label, line, at - (text.rfind("\n", 0, at) + 1) + 1)
    return Location(label)
