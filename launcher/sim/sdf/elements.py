"""Which SDF elements launcher reads, which it accepts without effect, and which it reports.

An element launcher cannot express is one warning with its file:line, saying what is left out
and what the world will lack; elements with no effect on a simulation (GUI, rendering
hints, ODE solver tuning) pass silently, and so do custom elements (`<gz:policies>`), kept
and ignored as libsdformat keeps them (one whose prefix is neither declared nor Gazebo's is
a warning). Plugin elements become plugin configs.
"""

from __future__ import annotations

from launcher.sim.mjcf import PluginConfig
from launcher.sim.sdf.context import Context
from launcher.sim.sdf.xmltree import Element, custom

KNOWN_PREFIXES = {"gz", "ignition"}  # Gazebo's own custom elements, used undeclared

READ = {
    "world": {"physics", "gravity", "light", "scene", "model", "include", "plugin", "frame"},
    "model": {"link", "joint", "plugin", "model", "include", "frame", "pose", "static"},
    "link": {"pose", "inertial", "collision", "visual", "gravity", "sensor"},
}
QUIET = {
    "world": {"gui", "atmosphere", "spherical_coordinates", "magnetic_field", "audio"},
    "model": {"self_collide", "allow_auto_disable", "enable_wind"},
    "link": {"self_collide", "must_be_base_link", "velocity_decay", "enable_wind"},
}
LACKS = {
    "actor": "animated actors are not simulated: the world has no actor here",
    "population": "populations are not expanded: the world lacks those models",
    "road": "roads are not built: the world has no road here",
    "wind": "there is no wind in the world",
    "state": "saved states are not applied: models start at their <pose>",
    "kinematic": "kinematic links are simulated as dynamic ones",
    "light": "lights attached to links are left out",
    "projector": "projectors are left out",
    "audio_source": "sound is not simulated",
    "audio_sink": "sound is not simulated",
    "battery": "batteries are not simulated",
    "particle_emitter": "particle emitters are left out",
    "gripper": "Gazebo's gripper helper is not simulated: grasping relies on contacts only",
}


def check_children(element: Element, context: Context) -> None:
    """Warn once for each child of `element` that launcher leaves out."""
    kind = element.tag
    for child in element.children:
        tag = child.tag
        found = custom(child)
        if found is not None:  # SDFormat's custom elements are kept and ignored
            name, prefix, declared = found
            if not declared and prefix not in KNOWN_PREFIXES:
                context.warn(child, f"custom element <{name}>: its prefix '{prefix}' is not "
                                    f"declared (xmlns:{prefix}=\"…\" on <sdf>); it is kept "
                                    f"and ignored")
            continue
        if tag in READ.get(kind, ()) or tag in QUIET.get(kind, ()):
            continue
        if tag in LACKS:
            context.warn(child, f"<{tag}> in <{kind}> is ignored: {LACKS[tag]}")
        else:
            context.warn(child, f"<{tag}> in <{kind}> is not known to launcher and is ignored")


def plugin_configs(element: Element) -> list[PluginConfig]:
    """The `<plugin>` children of a world, model or include, as the sim's plugin configs."""
    configs = []
    for plugin in element.findall("plugin"):
        filename = plugin.get("filename", "") or plugin.get("name", "")
        configs.append(PluginConfig(filename, plugin.get("name", ""), plugin,
                                    _Where(plugin)))  # type: ignore[arg-type]
    return configs


class _Where:
    """A plugin's file:line, found only when a message prints it."""

    def __init__(self, element: Element) -> None:
        self.element = element

    def __str__(self) -> str:
        location = self.element.location
        return f"{location.file}:{location.line}"

    def __format__(self, spec: str) -> str:
        return format(str(self), spec)
