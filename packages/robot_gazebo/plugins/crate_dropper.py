"""A world plugin, as the course's world plugin: when the world loads it spawns a model.

Declared in worlds/robot.world as <plugin filename="crate_dropper" name="CrateDropper">, found
through GZ_SIM_SYSTEM_PLUGIN_PATH (robot_gazebo's hooks put this folder there). Config:
<model> (a model:// URI or file: model://crate is model.config + model.sdf) and <pose>
(x y z roll pitch yaw).
"""

from launcher.sim.plugins import Plugin


class CrateDropper(Plugin):
    def load(self):
        pose = [float(v) for v in (self.text("pose") or "5 4 0.2 0 0 0").split()]
        entity = self.sim.spawn_file(self.text("model") or "model://crate", "crate", pose,
                                     allow_renaming=True)
        self.sim.transport.logger.info(f"CrateDropper: spawned '{entity.name}' at {pose[:3]}")
