"""The world: one MjSpec, its model and data, its entities, and its plugins.

Every model of the world file is an entity (an SDF `<model>`; an MJCF top-level body), as is
everything spawned: listed, moved, removed and reset alike. An entity's pose is its model
frame's (its root body's pose times the inverse of `offset`); a static entity has no joint
and is moved by moving its body.

Spawning copies a description's template, gives its root body a free joint, lets its plugins
add actuators, attaches it at a frame with the prefix `<name>/`, and recompiles keeping the
state (qpos, qvel, ctrl, time) of everything already there. A spawn that fails anywhere
leaves the world as it was. Recompiling makes new model and data objects: every plugin is
re-bound after it.

The world talks to the bus only through `transport` (publisher / subscribe / message /
logger), so it can be stepped without one.
"""

from __future__ import annotations

import contextlib
import math
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import mujoco
import numpy as np

from launcher.errors import LaunchError, Location, did_you_mean
from launcher.sim.loading import WorldModel, load_world_file
from launcher.sim.mjcf import PluginConfig
from launcher.sim.plugins import (
    Plugin,
    PluginError,
    PluginUnavailable,
    find_class,
    is_infrastructure,
)
from launcher.sim.templates import Template, Templates
from launcher.sim.transform import IDENTITY, Pose, PoseError, check_pose, pose_from
from launcher.sim.transport import Transport
from launcher.user_files import read_text

UNSTABLE = (mujoco.mjtWarning.mjWARN_BADQPOS, mujoco.mjtWarning.mjWARN_BADQVEL,
            mujoco.mjtWarning.mjWARN_BADQACC)
_QPOS, _QVEL, _QACC = (int(kind) for kind in UNSTABLE)  # indices into data.warning
MAX_SPEED = 1e4  # m/s and rad/s: the fastest a set_model_state may make an entity move
_NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")


class SpawnError(LaunchError):
    pass


@dataclass
class Entity:
    name: str
    anchors: list[Any]  # what removing it deletes from the spec: its frame or root bodies
    root: str  # its root body, prefixed
    label: str  # where its description came from
    plugins: list[Plugin] = field(default_factory=list)
    offset: Pose = IDENTITY  # the root body's pose in the model frame
    roots: list[str] = field(default_factory=list)  # every root body (several trees)
    body: int = -1  # bound after each recompile
    qpos: int = -1  # address of its free joint's qpos, -1 if none
    dof: int = -1
    placed: dict[str, Pose] = field(default_factory=dict)  # static roots as loaded


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

    @classmethod
    def from_path(cls, path: Path, transport: Transport, values: Mapping[str, str] | None = None,
                  environ: Mapping[str, str] | None = None) -> World:
        """The world of an SDF or MJCF file (a `.j2` rendered with `values`); what the file
        holds that launcher leaves out is logged, once each."""
        loaded = load_world_file(path, values, environ)
        for warning in loaded.warnings:
            transport.logger.warning(warning)
        world = cls(loaded.spec, loaded.label, transport, loaded.plugins, models=loaded.models)
        world.real_time_factor = loaded.real_time_factor
        return world

    def __init__(self, spec: mujoco.MjSpec, label: str, transport: Transport,
                 plugins: Sequence[PluginConfig] = (),
                 templates: Templates | None = None,
                 models: Sequence[WorldModel] | None = None) -> None:
        """`models`: the world file's models (SDF); None takes MJCF's top-level bodies."""
        self.spec, self.label, self.transport = spec, label, transport
        self.world_name = world_name(spec.modelname)
        if self.world_name not in (spec.modelname, "default"):
            transport.logger.warning(f"world name '{spec.modelname}' is not a valid ROS name "
                                     f"part; its topics use '{self.world_name}'")
        self.templates = templates or Templates()
        self.entities: dict[str, Entity] = {}
        self.iterations = 0
        self.plugins: list[Plugin] = []  # world plugins
        self._unstable = dict.fromkeys(UNSTABLE, 0)
        self._unstable_total = 0
        self._plugin_configs = list(plugins)
        self._all: list[Plugin] = []
        self._pre: list[Plugin] = []
        self._post: list[Plugin] = []
        self._warned: set[str] = set()
        for model in models if models is not None else _top_level_models(spec):
            self._add_world_model(model)
        self.model = _compile(spec, label)
        self.data = mujoco.MjData(self.model)
        self._plugins_changed()
        self._rebind(self.model, self.data)
        for entity in list(self.entities.values()):
            self._load_entity_plugins(entity)

    def _add_world_model(self, model: WorldModel) -> None:
        anchors = [self.spec.body(root) for root in model.roots]
        entity = Entity(model.name, anchors, model.root, self.label, offset=model.offset,
                        roots=list(model.roots))
        entity.plugins = [p for p in (self._make_plugin(c, entity) for c in model.plugins) if p]
        for plugin in list(entity.plugins):
            plugin.spec_prefix = f"{model.name}/"
            try:
                plugin.prepare(self.spec)
            except Exception as exc:  # a plugin's bug or bad config: the world still loads
                message = str(exc) if isinstance(exc, LaunchError) else \
                    f"plugin {plugin.label}: {type(exc).__name__}: {exc}"
                self.transport.logger.error(f"{message}; entity '{model.name}' runs without it")
                entity.plugins.remove(plugin)
        self.entities[model.name] = entity

    def _load_entity_plugins(self, entity: Entity) -> None:
        for plugin in list(entity.plugins):
            try:
                plugin.load()
            except Exception as exc:
                self._plugin_failed(plugin, "load", exc)

    # --- plugins ---------------------------------------------------------------------------
    def load_world_plugins(self, before: Sequence[PluginConfig] = ()) -> None:
        """Load `before` (the sim's own) and the world file's plugins; one that fails is
        logged and left out."""
        for config in [*before, *self._plugin_configs]:
            plugin = self._make_plugin(config, None)
            if plugin is None:
                continue
            try:
                plugin.bind(self.model, self.data)
                plugin.load()
            except Exception as exc:
                self._plugin_failed(plugin, "load", exc)
                continue
            self.plugins.append(plugin)
            self._plugins_changed()

    def _make_plugin(self, config: PluginConfig, entity: Entity | None) -> Plugin | None:
        if is_infrastructure(config):
            return None  # Gazebo's physics, user commands, …: what the sim is by itself
        try:
            cls = find_class(config)
            return cls(self, entity, config)
        except PluginUnavailable as exc:
            self.transport.logger.warning(str(exc))
        except PluginError as exc:
            self.transport.logger.error(str(exc))
        except Exception as exc:
            self.transport.logger.error(f"{config.where}: plugin {config.name or config.filename}"
                                        f" failed to start: {type(exc).__name__}: {exc}")
        return None

    def _plugin_failed(self, plugin: Plugin, hook: str, exc: BaseException) -> None:
        owner = f" of entity '{plugin.entity.name}'" if plugin.entity is not None else ""
        self.transport.logger.error(
            f"plugin {plugin.label}{owner} raised in {hook}: {type(exc).__name__}: {exc}; "
            "the sim goes on without it")
        for group in (self.plugins, *(e.plugins for e in self.entities.values())):
            if plugin in group:
                group.remove(plugin)
        self._plugins_changed()
        with contextlib.suppress(Exception):  # already failing: its close may fail too
            plugin.close()

    def all_plugins(self) -> list[Plugin]:
        return self._all

    def _plugins_changed(self) -> None:
        """Refresh the lists the step loop walks (built once, not per step)."""
        found = list(self.plugins)
        for entity in self.entities.values():
            found += entity.plugins
        self._all = found
        self._pre = [p for p in found if type(p).pre_step is not Plugin.pre_step]
        # only these bound the batches: a plugin without a post_step (one that spawns a
        # model at load) would otherwise make every batch a single step
        self._post = [p for p in found if type(p).post_step is not Plugin.post_step]

    # --- stepping --------------------------------------------------------------------------
    def steps_until_update(self, limit: int) -> int:
        """How many steps may run before a plugin needs its post_step (at least 1)."""
        if not self._post:
            return max(1, limit)
        due = min(p.next_update for p in self._post) - self.data.time
        return max(1, min(limit, math.ceil(due / self.model.opt.timestep - 1e-9)))

    def step(self, count: int = 1) -> None:
        """Step `count` times; pre_step hooks run before, post_step hooks that are due after."""
        model, data = self.model, self.data
        for plugin in self._pre:
            try:
                plugin.pre_step(model, data)
            except Exception as exc:
                self._plugin_failed(plugin, "pre_step", exc)
        mujoco.mj_step(model, data, nstep=count)
        self.iterations += count
        warnings = data.warning  # MuJoCo counts bad qpos/qvel/qacc, then resets the state
        if warnings[_QPOS].number + warnings[_QVEL].number + warnings[_QACC].number != \
                self._unstable_total:
            self._check_unstable()
        now = data.time + 1e-9
        for plugin in self._post:
            if plugin.next_update <= now:
                try:
                    plugin.post_step(model, data)
                except Exception as exc:
                    self._plugin_failed(plugin, "post_step", exc)

    def _check_unstable(self) -> None:
        data = self.data
        self._unstable_total = sum(data.warning[kind].number for kind in UNSTABLE)
        for kind in UNSTABLE:
            bad = data.warning[kind]
            if bad.number != self._unstable[kind]:
                self._unstable[kind] = bad.number
                self._report_blow_up(int(bad.lastinfo), kind.name.removeprefix("mjWARN_BAD"))

    def _report_blow_up(self, dof: int, what: str) -> None:
        owner = "the world"
        if 0 <= dof < self.model.nv:
            body = self.model.body(int(self.model.dof_bodyid[dof])).name
            owner = f"entity '{body.split('/')[0]}'" if "/" in body else f"body '{body}'"
        self.transport.logger.warning(
            f"physics became unstable at t={self.data.time:.3f}s (MuJoCo: NaN or huge {what} "
            f"at degree of freedom {dof}, {owner}); MuJoCo reset the state; the sim goes on")
        for plugin in self.all_plugins():
            plugin.reset()

    # --- entities --------------------------------------------------------------------------
    def unique_name(self, name: str, allow_renaming: bool) -> str:
        if not _NAME.match(name):
            raise SpawnError(f"invalid entity name '{name}': use letters, digits and '_' "
                             "(it prefixes every body, joint and topic of the entity)")
        if name not in self.entities and not self._name_in_model(name):
            return name
        if not allow_renaming:
            raise SpawnError(f"an entity named '{name}' already exists; choose another name or "
                             "set allow_renaming")
        number = 1
        while f"{name}_{number}" in self.entities or self._name_in_model(f"{name}_{number}"):
            number += 1
        return f"{name}_{number}"

    def _name_in_model(self, name: str) -> bool:
        prefix = f"{name}/"
        return any(b.name.startswith(prefix) or b.name == name for b in self.spec.bodies)

    def spawn(self, template: Template, name: str, position: Sequence[float],
              quat: Sequence[float], allow_renaming: bool = False,
              joints: Mapping[str, float] | None = None) -> Entity:
        """Add the template as entity `name`; `joints` gives hinge and slide joints their first
        positions (a reset puts them back at zero, as the model has them)."""
        _checked(position, quat)
        name = self.unique_name(name or template.name, allow_renaming)
        for warning in template.warnings:
            if warning not in self._warned:
                self._warned.add(warning)
                self.transport.logger.warning(warning)
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
                for geom in body.geoms:  # contacts take the larger friction unless the
                    geom.friction[0] = mu  # geom has priority over what it touches
                    geom.priority = max(geom.priority, 1)
        _check_joints(child, joints or {}, template.label)
        root = template.root or roots[0].name
        entity = Entity(name, [], f"{name}/{root}", template.label, offset=template.offset,
                        roots=[f"{name}/{body.name}" for body in roots])
        plugins = [p for p in (self._make_plugin(c, entity) for c in template.plugins) if p]
        for plugin in plugins:
            try:
                plugin.prepare(child)
            except LaunchError as exc:
                raise SpawnError(str(exc)) from None
        frame = self.spec.worldbody.add_frame(pos=list(position), quat=list(quat))
        try:
            self.spec.attach(child, frame=frame, prefix=f"{name}/")
            self.spec.dedup_assets()  # ten copies of a robot share its meshes
            model, data = self.spec.recompile(self.model, self.data)
        except Exception as exc:
            self.spec.delete(frame)
            raise SpawnError(f"{template.label}: MuJoCo could not add '{name}': "
                             f"{' '.join(str(exc).split())}") from None
        entity.anchors = [frame]
        entity.plugins = plugins
        self.entities[name] = entity
        self._plugins_changed()
        self._rebind(model, data)
        if joints:
            for joint, value in joints.items():
                index = self.model.joint(f"{name}/{joint}").id
                self.data.qpos[self.model.jnt_qposadr[index]] = value
            mujoco.mj_forward(self.model, self.data)
        self._load_entity_plugins(entity)
        return entity

    def spawn_file(self, uri: str, name: str, pose: Sequence[float] = (0, 0, 0, 0, 0, 0),
                   allow_renaming: bool = False) -> Entity:
        """Spawn from a file or `model://`/`package://` URI at (x, y, z, roll, pitch, yaw)."""
        position, quat = pose_from(list(pose))
        return self.spawn(self.templates.from_file(uri), name, position, quat,
                          allow_renaming)

    def remove(self, name: str) -> None:
        entity = self.entity(name)
        for anchor in entity.anchors:
            self.spec.delete(anchor)
        model, data = self.spec.recompile(self.model, self.data)
        del self.entities[name]
        self._plugins_changed()
        for plugin in entity.plugins:
            plugin.close()
        self._rebind(model, data)

    def entity(self, name: str) -> Entity:
        if name not in self.entities:
            raise SpawnError(f"no entity named '{name}'"
                             f"{did_you_mean(name, list(self.entities))}")
        return self.entities[name]

    def set_pose(self, name: str, position: Sequence[float], quat: Sequence[float]) -> None:
        """Put the entity's model frame at `position`/`quat` (w, x, y, z), at rest."""
        entity = self.entity(name)
        _checked(position, quat)
        norm = math.sqrt(sum(q * q for q in quat))
        target = Pose(tuple(position), tuple(q / norm for q in quat)) * entity.offset
        move = target * self._body_pose(entity.body).inverse()
        for root in entity.roots:
            self._place_root(self.model.body(root).id, move)
        mujoco.mj_forward(self.model, self.data)

    def set_twist(self, name: str, linear: Sequence[float], angular: Sequence[float]) -> None:
        """Give the entity's root this velocity (world frame); one without a free joint (a
        static model) cannot move and says so."""
        entity = self.entity(name)
        if entity.dof < 0:
            raise SpawnError(f"'{name}' has no free joint (a static model): it cannot be "
                             "given a velocity")
        for value in (*linear, *angular):
            if not math.isfinite(value) or abs(value) > MAX_SPEED:
                raise SpawnError(f"velocity {value} of '{name}' is not a finite number "
                                 f"within ±{MAX_SPEED:g}")
        self.data.qvel[entity.dof:entity.dof + 3] = linear
        local = np.zeros(3)
        inverse = np.zeros(4)
        mujoco.mju_negQuat(inverse, self.data.xquat[entity.body])
        mujoco.mju_rotVecQuat(local, np.asarray(angular, dtype=float), inverse)
        self.data.qvel[entity.dof + 3:entity.dof + 6] = local
        mujoco.mj_forward(self.model, self.data)

    def _body_pose(self, body: int) -> Pose:
        return Pose(tuple(self.data.xpos[body].tolist()), tuple(self.data.xquat[body].tolist()))

    def _place_root(self, body: int, move: Pose) -> None:
        """Move a root body by `move`: its free joint's qpos, or (no joint) the body itself."""
        placed = move * self._body_pose(body)
        joint = int(self.model.body_jntadr[body])
        if joint >= 0 and self.model.jnt_type[joint] == mujoco.mjtJoint.mjJNT_FREE:
            address, dof = int(self.model.jnt_qposadr[joint]), int(self.model.jnt_dofadr[joint])
            self.data.qpos[address:address + 7] = [*placed.pos, *placed.quat]
            self.data.qvel[dof:dof + 6] = 0.0
        else:
            self._put_static(body, placed)

    def _put_static(self, body: int, pose: Pose) -> None:
        """A jointless root body: the model's pose now, the spec's for later recompiles."""
        self.model.body_pos[body], self.model.body_quat[body] = pose.pos, pose.quat
        element = self.spec.body(self.model.body(body).name)
        frame = element.frame
        local = frame_pose(frame).inverse() * pose if frame is not None else pose
        element.pos, element.quat = list(local.pos), list(local.quat)

    def _rebind(self, model: Any, data: Any) -> None:
        self.model, self.data = model, data
        self._unstable = {kind: data.warning[kind].number for kind in UNSTABLE}
        self._unstable_total = sum(self._unstable.values())
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
        for plugin in self.all_plugins():
            try:
                plugin.bind(model, data)
            except Exception as exc:
                self._plugin_failed(plugin, "bind", exc)

    # --- resets ----------------------------------------------------------------------------
    def reset(self, time: bool = True, poses: bool = True) -> None:
        """Reset all (both), time only, or poses only (Gazebo's WorldReset)."""
        if time and poses:
            mujoco.mj_resetData(self.model, self.data)
        elif poses:
            self.data.qpos[:] = self.model.qpos0
            self.data.qvel[:] = 0.0
            self.data.act[:] = 0.0
            self.data.ctrl[:] = 0.0
        if poses:
            for entity in self.entities.values():  # static entities that were moved
                for root, pose in entity.placed.items():
                    self._put_static(self.model.body(root).id, pose)
        if time:
            self.data.time = 0.0
            self.iterations = 0
        mujoco.mj_forward(self.model, self.data)
        for plugin in self.all_plugins():
            plugin.reset()

    # --- reading state ---------------------------------------------------------------------
    def poses(self) -> tuple[list[str], Any, Any]:
        """(names, positions n×3, quaternions n×4 as w,x,y,z) of every entity's model frame."""
        names = list(self.entities)
        ids = [self.entities[n].body for n in names]
        positions, quats = self.data.xpos[ids].copy(), self.data.xquat[ids].copy()
        for row, name in enumerate(names):
            offset = self.entities[name].offset
            if offset is not IDENTITY and not offset.is_identity:
                pose = self._body_pose(ids[row]) * offset.inverse()
                positions[row], quats[row] = pose.pos, pose.quat
        return names, positions, quats

    def velocities(self, names: Sequence[str]) -> list[list[float]]:
        """Each entity's root velocity (linear, angular); zeros for one without a free joint."""
        found = []
        for name in names:
            dof = self.entities[name].dof
            found.append(self.data.qvel[dof:dof + 6].tolist() if dof >= 0 else [0.0] * 6)
        return found


def _checked(position: Sequence[float], quat: Sequence[float]) -> None:
    try:
        check_pose(position, quat)
    except PoseError as exc:
        raise SpawnError(exc.message) from None


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
    """An MJCF world's models: its top-level bodies."""
    return [WorldModel(body.name, body.name, [body.name]) for body in spec.worldbody.bodies
            if body.name]


def frame_pose(frame: Any) -> Pose:
    return Pose(tuple(frame.pos), tuple(frame.quat))


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
