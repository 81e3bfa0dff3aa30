"""The contact sensor: the touches of the link's collisions that `<contact><collision>` names,
read from MuJoCo's contacts after each step and published (as gz-sim's Contact system does)
only while there are any: each touching pair once, with every point where they touch, the
normal there, the depth, and the contact force on each side.

Collisions are named as Gazebo names them (`model::link::collision`); a URDF's are named as
Gazebo's URDF import names them (`<link>_collision`, `<link>_collision_1`, …, and
`<parent>_fixed_joint_lump__<link>_collision` for a link lumped into its parent).
"""

from __future__ import annotations

from typing import Any

import mujoco
import numpy as np

from launcher.errors import did_you_mean
from launcher.sim.sensors.base import Sensor

COLLISION = 5  # ros_gz_interfaces/Entity's COLLISION


class Contact(Sensor):
    message_type = "mujoco_sim/msg/Contacts"
    suffix = "contact"

    def configure(self) -> None:
        settings = self.config.element.find("contact")
        self.wanted = [c.stripped for c in settings.iterfind("collision")] \
            if settings is not None else []
        self.contact_topic = (settings.value("topic") if settings is not None else None) or ""
        if not self.wanted:
            self.sim.transport.logger.warning(
                f"{self.config.where}: {self.label} names no <contact><collision>: it reports "
                "nothing")

    def topic_name(self, suffix: str | None = None) -> str:
        """`<contact><topic>` where the sensor has no `<topic>` (gz-sim's older spelling)."""
        if self.contact_topic and not self.config.topic:
            return self.contact_topic if self.contact_topic.startswith("/") else \
                f"/{self.contact_topic}"
        return super().topic_name(suffix)

    def bind(self, model: Any, data: Any) -> None:
        super().bind(model, data)
        body = int(model.site_bodyid[self.site])
        own = {self._own_name(model, geom, index): geom
               for index, geom in enumerate(_collisions(model, body))}
        self.geoms = {own[name] for name in self.wanted if name in own}
        lost = [name for name in self.wanted if name not in own]
        if lost and not getattr(self, "told", False):
            self.told = True
            self.sim.transport.logger.warning(
                f"{self.config.where}: {self.label}: link '{self.config.scope_link}' has no "
                f"collision '{lost[0]}'{did_you_mean(lost[0], list(own))} (its collisions: "
                f"{', '.join(own) or 'none'}); it is not watched")
        self.names: dict[int, str] = {
            geom: f"{self.entity.name}::{self.config.scope_link}::{name}"
            for name, geom in own.items()}

    def _own_name(self, model: Any, geom: int, index: int) -> str:
        """A geom of the sensor's link by the name `<contact><collision>` gives it."""
        name = model.geom(geom).name
        if "/collision/" in name:  # an SDF collision
            return name.rsplit("/collision/", 1)[1]
        link = self.config.link.rsplit("::", 1)[-1]
        base = f"{link}_collision" if self.config.scope_link == self.config.link else \
            f"{self.config.scope_link}_fixed_joint_lump__{link}_collision"
        return base if index == 0 else f"{base}_{index}"

    def scoped(self, model: Any, geom: int) -> str:
        """Gazebo's scoped name of any geom: `model::link::collision`."""
        found = self.names.get(geom)
        if found is None:
            name = model.geom(geom).name
            if "/collision/" in name:
                owner, collision = name.rsplit("/collision/", 1)
                found = f"{owner.replace('/', '::')}::{collision}"
            else:  # a URDF's or MJCF's: named by its link, as Gazebo's URDF import names it
                body = int(model.geom_bodyid[geom])
                owner = model.body(body).name or "world"
                link = owner.rsplit("/", 1)[-1]
                collisions = _collisions(model, body)
                index = collisions.index(geom) if geom in collisions else 0
                found = f"{owner.replace('/', '::')}::" + \
                    (name.rsplit("/", 1)[-1] if name else
                     f"{link}_collision{f'_{index}' if index else ''}")
            self.names[geom] = found
        return found

    def measure(self, model: Any, data: Any) -> Any:
        count = data.ncon
        if not self.geoms or count == 0:
            return self._empty(data)
        contacts = data.contact
        first, second = contacts.geom1[:count], contacts.geom2[:count]
        pairs: dict[tuple[int, int], list[int]] = {}
        for index in range(count):
            a, b = int(first[index]), int(second[index])
            if a in self.geoms:
                pairs.setdefault((a, b), []).append(index)
            elif b in self.geoms:
                pairs.setdefault((b, a), []).append(index)
        if not pairs:
            return self._empty(data)
        transport = self.sim.transport
        return transport.message(self.message_type, header=self.header(data), contacts=[
            self._contact(model, data, mine, other, indices)
            for (mine, other), indices in pairs.items()])

    def _empty(self, data: Any) -> Any:
        """No touch: nothing on the sim's topic, and an empty reading for a gazebo_ros bumper
        (which reports every update)."""
        if not self.ros.outputs:
            return None
        return self.sim.transport.message(self.message_type, header=self.header(data),
                                          contacts=[])

    def reports(self, message: Any) -> bool:
        return bool(message.contacts)

    def _contact(self, model: Any, data: Any, mine: int, other: int,
                 indices: list[int]) -> Any:
        transport, contacts = self.sim.transport, data.contact
        positions, normals, depths, wrenches = [], [], [], []
        force = np.zeros(6)
        for index in indices:
            frame = contacts.frame[index].reshape(3, 3)
            # MuJoCo's normal points from geom1 to geom2, and its force acts on geom2
            sign = 1.0 if int(contacts.geom1[index]) == mine else -1.0
            mujoco.mj_contactForce(model, data, index, force)
            on_other = sign * (frame.T @ force[:3])
            positions.append(transport.vector(*contacts.pos[index]))
            normals.append(transport.vector(*(sign * frame[0])))
            depths.append(float(-contacts.dist[index]))
            wrenches.append(transport.message(
                "ros_gz_interfaces/msg/JointWrench", header=self.header(data),
                body_1_name=transport.message("std_msgs/msg/String",
                                              data=self.scoped(model, mine)),
                body_1_id=transport.message("std_msgs/msg/UInt32", data=mine),
                body_2_name=transport.message("std_msgs/msg/String",
                                              data=self.scoped(model, other)),
                body_2_id=transport.message("std_msgs/msg/UInt32", data=other),
                body_1_wrench=self._wrench(-on_other), body_2_wrench=self._wrench(on_other)))
        entity = "ros_gz_interfaces/msg/Entity"
        return transport.message(
            "ros_gz_interfaces/msg/Contact",
            collision1=transport.message(entity, id=mine, name=self.scoped(model, mine),
                                         type=COLLISION),
            collision2=transport.message(entity, id=other, name=self.scoped(model, other),
                                         type=COLLISION),
            positions=positions, normals=normals, depths=depths, wrenches=wrenches)

    def _wrench(self, force: Any) -> Any:
        transport = self.sim.transport
        return transport.message("geometry_msgs/msg/Wrench", force=transport.vector(*force),
                                 torque=transport.vector(0.0, 0.0, 0.0))


def _collisions(model: Any, body: int) -> list[int]:
    """The geoms of `body` that collide (not its visuals), in order."""
    start = int(model.body_geomadr[body])
    return [g for g in range(start, start + int(model.body_geomnum[body]))
            if model.geom_contype[g] or model.geom_conaffinity[g]]
