"""The services of mujoco_ros2_control's `mujoco_ros2_control_node`, as it offers them:
`~/set_pause`, `~/step_simulation` (a paused sim, answered once the steps are done),
`~/reset_world` (to the start-up state or an MJCF keyframe, with joint and free-joint
overrides) and `~/set_free_joint_state` (all entries checked before any is applied).

Sim time goes on across a reset, as mujoco_ros2_control keeps the ROS clock continuous.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import mujoco
import numpy as np

from launcher.errors import did_you_mean

TYPES = "mujoco_ros2_control_msgs/srv"
STEP_TIMEOUT = 30.0  # s of wall time, or 10 ms a step if longer (mujoco_ros2_control's)


class Refused(Exception):
    """A request that cannot be done: its message goes back with success false."""


class SimServices:
    def __init__(self, node: Any, server: Any, world: Any,
                 after_reset: Callable[[], None]) -> None:
        self.node, self.server, self.world = node, server, world
        self.after_reset = after_reset
        self.log = node.get_logger()
        self.initial = self._capture()
        node.create_service(f"{TYPES}/SetPause", "~/set_pause", self.on_set_pause)
        step = node.create_service(f"{TYPES}/StepSimulation", "~/step_simulation",
                                   self.on_step)
        step.deferred = True
        node.create_service(f"{TYPES}/ResetWorld", "~/reset_world", self.on_reset)
        node.create_service(f"{TYPES}/SetFreeJointState", "~/set_free_joint_state",
                            self.on_set_free_joints)

    def _capture(self) -> dict[str, np.ndarray]:
        data = self.world.data
        return {name: getattr(data, name).copy() for name in ("qpos", "qvel", "ctrl", "act")}

    # --- pause and step -------------------------------------------------------------------
    def on_set_pause(self, request: Any, response: Any) -> Any:
        self.server.set_paused(bool(request.paused))
        response.success = True
        response.message = "paused" if request.paused else "running"
        return response

    def on_step(self, request: Any, reply: Any) -> None:
        response = reply.new_response()
        if request.steps < 1:
            response.success, response.message = False, "steps must be at least 1"
            reply.send(response)
            return
        if not self.server.paused:
            response.success = False
            response.message = "the simulation is running: pause it (~/set_pause) first"
            reply.send(response)
            return
        start = self.world.physics.iterations

        def done(finished: bool) -> None:
            stepped = self.world.physics.iterations - start
            response.success = finished
            response.message = (f"stepped {stepped} steps" if finished else
                                f"interrupted after {stepped} of {request.steps} steps")
            reply.send(response)

        self.server.step_then(int(request.steps), done)

    # --- reset ----------------------------------------------------------------------------
    def on_reset(self, request: Any, response: Any) -> Any:
        world = self.world
        model, data = world.model, world.data
        saved = self._capture()
        now = float(data.time)
        try:
            if request.keyframe:
                keys = [model.key(i).name for i in range(model.nkey)]
                if request.keyframe not in keys:
                    raise Refused(f"no keyframe '{request.keyframe}' in the model"
                                  f"{did_you_mean(request.keyframe, keys)} (keyframes: "
                                  f"{', '.join(keys) or 'none'})")
                mujoco.mj_resetDataKeyframe(model, data, keys.index(request.keyframe))
            else:
                mujoco.mj_resetData(model, data)
                for name, value in self.initial.items():
                    getattr(data, name)[:] = value
            data.time = now
            self._joint_overrides(request.state_overrides.joint_states)
            mujoco.mj_forward(model, data)
            self._free_joints(request.state_overrides.free_joints)
        except Refused as exc:
            for name, value in saved.items():
                getattr(data, name)[:] = value
            mujoco.mj_forward(model, data)
            response.success, response.message = False, str(exc)
            return response
        mujoco.mj_forward(model, data)
        self.after_reset()
        response.success = True
        response.message = (f"reset to keyframe '{request.keyframe}'" if request.keyframe
                            else "reset to the start-up state")
        return response

    def _joint_overrides(self, states: Any) -> None:
        model, data = self.world.model, self.world.data
        names = list(states.name)
        positions, velocities = list(states.position), list(states.velocity)
        for label, values in (("position", positions), ("velocity", velocities)):
            if values and len(values) != len(names):
                raise Refused(f"state_overrides.joint_states: {len(names)} names but "
                              f"{len(values)} {label}s: give one per name, or none")
        if len(states.effort):
            raise Refused("state_overrides.joint_states: effort cannot be set; leave it empty")
        moving = (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE))
        joints = [model.joint(i).name for i in range(model.njnt)]
        for index, name in enumerate(names):
            joint = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, name)
            if joint < 0:
                raise Refused(f"state_overrides.joint_states: no joint '{name}'"
                              f"{did_you_mean(name, joints)}")
            if int(model.jnt_type[joint]) not in moving:
                raise Refused(f"state_overrides.joint_states: '{name}' is not a hinge or "
                              f"slide joint (set a free joint's body in free_joints)")
            if positions:
                data.qpos[model.jnt_qposadr[joint]] = positions[index]
            if velocities:
                data.qvel[model.jnt_dofadr[joint]] = velocities[index]

    # --- free joints ----------------------------------------------------------------------
    def on_set_free_joints(self, request: Any, response: Any) -> Any:
        try:
            self._free_joints(request.free_joints)
        except Refused as exc:
            response.success, response.message = False, str(exc)
            return response
        response.success = True
        response.message = f"set {len(request.free_joints)} free joint(s)"
        return response

    def _free_joints(self, entries: Any) -> None:
        """Check every entry, then apply them in order (the last of a body wins)."""
        model, data = self.world.model, self.world.data
        planned = []
        bodies = [model.body(i).name for i in range(model.nbody)]
        for index, entry in enumerate(entries):
            where = f"free_joints[{index}] '{entry.name}'"
            body = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, entry.name)
            if body < 0:
                raise Refused(f"{where}: no body of that name{did_you_mean(entry.name, bodies)}")
            joint = next((j for j in range(model.body_jntadr[body],
                                           model.body_jntadr[body] + model.body_jntnum[body])
                          if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE), None) \
                if model.body_jntnum[body] else None
            if joint is None:
                raise Refused(f"{where}: the body is not driven by a free joint")
            frames = []
            for part in (entry.pose.header.frame_id, entry.twist.header.frame_id):
                frame = -1
                if part:
                    frame = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, part)
                    if frame < 0:
                        raise Refused(f"{where}: frame_id '{part}' is not a body"
                                      f"{did_you_mean(part, bodies)}")
                frames.append(frame)
            planned.append((entry, joint, frames))
        for entry, joint, (pose_frame, twist_frame) in planned:
            p, o = entry.pose.pose.position, entry.pose.pose.orientation
            position = np.array([p.x, p.y, p.z])
            quat = np.array([o.w, o.x, o.y, o.z], dtype=float)
            norm = float(np.linalg.norm(quat))
            quat = np.array([1.0, 0, 0, 0]) if norm == 0 or not math.isfinite(norm) \
                else quat / norm
            if pose_frame >= 0:
                frame_quat = data.xquat[pose_frame].copy()
                moved = np.zeros(3)
                mujoco.mju_rotVecQuat(moved, position, frame_quat)
                position = data.xpos[pose_frame] + moved
                combined = np.zeros(4)
                mujoco.mju_mulQuat(combined, frame_quat, quat)
                quat = combined
            t = entry.twist.twist
            linear = np.array([t.linear.x, t.linear.y, t.linear.z])
            angular = np.array([t.angular.x, t.angular.y, t.angular.z])
            if twist_frame >= 0:
                frame_quat = data.xquat[twist_frame].copy()
                for vector in (linear, angular):
                    rotated = np.zeros(3)
                    mujoco.mju_rotVecQuat(rotated, vector, frame_quat)
                    vector[:] = rotated
            address, dof = model.jnt_qposadr[joint], model.jnt_dofadr[joint]
            data.qpos[address:address + 3] = position
            data.qpos[address + 3:address + 7] = quat
            data.qvel[dof:dof + 3] = linear
            # a free joint's angular velocity is in the body's frame in MuJoCo
            local = np.zeros(3)
            inverse = np.zeros(4)
            mujoco.mju_negQuat(inverse, quat)
            mujoco.mju_rotVecQuat(local, angular, inverse)
            data.qvel[dof + 3:dof + 6] = local
        mujoco.mj_forward(model, data)
