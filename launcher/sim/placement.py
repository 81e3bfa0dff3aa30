"""Where the entities are and how fast they go: each entity's model-frame pose and root
velocity, read as whole arrays, and set (a pose at rest; a velocity on a free joint). A static
entity has no joint: it is moved by moving its body, in the model and in the spec, so that a
later recompile keeps it there."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import mujoco
import numpy as np

from launcher.sim.entity import SpawnError
from launcher.sim.transform import IDENTITY, Pose, PoseError, check_pose

MAX_SPEED = 1e4  # m/s and rad/s: the fastest a set_model_state may make an entity move


class Placement:
    def __init__(self, world: Any) -> None:
        self.world = world  # its model, data and spec change with every recompile

    def set_pose(self, name: str, position: Sequence[float], quat: Sequence[float]) -> None:
        """Put the entity's model frame at `position`/`quat` (w, x, y, z), at rest."""
        world = self.world
        entity = world.entity(name)
        checked(position, quat)
        norm = math.sqrt(sum(q * q for q in quat))
        target = Pose(tuple(position), tuple(q / norm for q in quat)) * entity.offset
        move = target * self.body_pose(entity.body).inverse()
        for root in entity.roots:
            self._place_root(world.model.body(root).id, move)
        mujoco.mj_forward(world.model, world.data)

    def set_twist(self, name: str, linear: Sequence[float], angular: Sequence[float]) -> None:
        """Give the entity's root this velocity (world frame); one without a free joint (a
        static model) cannot move and says so."""
        world = self.world
        entity = world.entity(name)
        if entity.dof < 0:
            raise SpawnError(f"'{name}' has no free joint (a static model): it cannot be "
                             "given a velocity")
        for value in (*linear, *angular):
            if not math.isfinite(value) or abs(value) > MAX_SPEED:
                raise SpawnError(f"velocity {value} of '{name}' is not a finite number "
                                 f"within ±{MAX_SPEED:g}")
        world.data.qvel[entity.dof:entity.dof + 3] = linear
        local = np.zeros(3)
        inverse = np.zeros(4)
        mujoco.mju_negQuat(inverse, world.data.xquat[entity.body])
        mujoco.mju_rotVecQuat(local, np.asarray(angular, dtype=float), inverse)
        world.data.qvel[entity.dof + 3:entity.dof + 6] = local
        mujoco.mj_forward(world.model, world.data)

    def poses(self) -> tuple[list[str], Any, Any]:
        """(names, positions n×3, quaternions n×4 as w,x,y,z) of every entity's model frame."""
        entities, data = self.world.entities, self.world.data
        names = list(entities)
        ids = [entities[n].body for n in names]
        positions, quats = data.xpos[ids].copy(), data.xquat[ids].copy()
        for row, name in enumerate(names):
            offset = entities[name].offset
            if offset is not IDENTITY and not offset.is_identity:
                pose = self.body_pose(ids[row]) * offset.inverse()
                positions[row], quats[row] = pose.pos, pose.quat
        return names, positions, quats

    def velocities(self, names: Sequence[str]) -> list[list[float]]:
        """Each entity's root velocity (linear, angular); zeros for one without a free joint."""
        found = []
        for name in names:
            dof = self.world.entities[name].dof
            found.append(self.world.data.qvel[dof:dof + 6].tolist() if dof >= 0 else [0.0] * 6)
        return found

    def body_pose(self, body: int) -> Pose:
        data = self.world.data
        return Pose(tuple(data.xpos[body].tolist()), tuple(data.xquat[body].tolist()))

    def _place_root(self, body: int, move: Pose) -> None:
        """Move a root body by `move`: its free joint's qpos, or (no joint) the body itself."""
        model, data = self.world.model, self.world.data
        placed = move * self.body_pose(body)
        joint = int(model.body_jntadr[body])
        if joint >= 0 and model.jnt_type[joint] == mujoco.mjtJoint.mjJNT_FREE:
            address, dof = int(model.jnt_qposadr[joint]), int(model.jnt_dofadr[joint])
            data.qpos[address:address + 7] = [*placed.pos, *placed.quat]
            data.qvel[dof:dof + 6] = 0.0
        else:
            self.put_static(body, placed)

    def put_static(self, body: int, pose: Pose) -> None:
        """A jointless root body: the model's pose now, the spec's for later recompiles."""
        model = self.world.model
        model.body_pos[body], model.body_quat[body] = pose.pos, pose.quat
        element = self.world.spec.body(model.body(body).name)
        frame = element.frame
        local = frame_pose(frame).inverse() * pose if frame is not None else pose
        element.pos, element.quat = list(local.pos), list(local.quat)


def checked(position: Sequence[float], quat: Sequence[float]) -> None:
    try:
        check_pose(position, quat)
    except PoseError as exc:
        raise SpawnError(exc.message) from None


def frame_pose(frame: Any) -> Pose:
    return Pose(tuple(frame.pos), tuple(frame.quat))
