"""An SDF `<world>` as an MjSpec: physics, gravity, lights, scene, models and plugins.

`<physics><max_step_size>` is MuJoCo's timestep and `<real_time_factor>` the sim's pacing;
each model is built straight into the world's spec (models of one name are an error); the
world's and the models' `<plugin>`s are handed to the sim, which loads Gazebo's systems
under their names.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import mujoco

from launcher.sim.mjcf import PluginConfig
from launcher.sim.sdf.context import Context, Origin, opened
from launcher.sim.sdf.elements import check_children, plugin_configs
from launcher.sim.sdf.model import BuiltModel, build, new_spec
from launcher.sim.sdf.pose import IDENTITY, Pose, number, numbers, parse_pose, rotate
from launcher.sim.sdf.xmltree import Element
from launcher.sim.sensors.geodesy import SphericalCoordinates

LIGHTS = {"directional": mujoco.mjtLightType.mjLIGHT_DIRECTIONAL,
          "point": mujoco.mjtLightType.mjLIGHT_POINT, "spot": mujoco.mjtLightType.mjLIGHT_SPOT}


MAGNETIC_FIELD = (5.5645e-6, 22.8758e-6, -42.3884e-6)  # tesla: SDFormat's default


@dataclass
class SdfWorld:
    spec: Any
    name: str
    models: list[BuiltModel]
    plugins: list[PluginConfig]
    real_time_factor: float | None
    warnings: list[str] = field(default_factory=list)
    spherical_coordinates: SphericalCoordinates = SphericalCoordinates()


def load_world(text: str, path: Path | None, environ: Mapping[str, str] | None = None,
               packages: Any = None) -> SdfWorld:
    world, origin, context = opened(text, path, "world", " (a model file is spawned with "
                                    "`create -file`, or included in a world)", environ, packages)
    spec = new_spec(world.get("name", "default"))
    # stable with the velocity actuators of wheels and joint servos (as for MJCF worlds)
    spec.option.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    check_children(world, context)
    rtf = _physics(spec, world)
    _gravity(spec, world)
    _magnetic_field(spec, world)
    _scene(spec, world)
    for light in world.findall("light"):
        add_light(spec, light)
    with context.inside(origin):
        models = _models(spec, world, origin, context)
    _world_frames(spec, world, context)
    return SdfWorld(spec, spec.modelname, models, plugin_configs(world), rtf, context.warnings,
                    _spherical_coordinates(world))


NAMED_POSE_GROUP = 5  # a site group the viewer does not draw


def _world_frames(spec: Any, world: Element, context: Context) -> None:
    """The world's own `<frame>`s, placed in the world frame, as sites of the world body (the
    standard API's named poses); one placed relative to a model is left out, said once."""
    for frame in world.findall("frame"):
        pose = frame.find("pose")
        anchors = {frame.get("attached_to", ""), pose.get("relative_to", "") if pose is not None
                   else ""}
        name = frame.get("name", "")
        if not name:
            continue
        if anchors - {"", "world"}:
            context.warn(frame, f"world frame '{name}': a frame placed relative to a model is "
                                "not a named pose yet (only frames in the world frame are)")
            continue
        placed = parse_pose(pose)
        spec.worldbody.add_site(name=name, pos=list(placed.pos), quat=list(placed.quat),
                                group=NAMED_POSE_GROUP)


def _magnetic_field(spec: Any, world: Element) -> None:
    """The world's `<magnetic_field>` (tesla, world frame), SDFormat's default when it has
    none, as MuJoCo's `option.magnetic` (what magnetometers read)."""
    found = world.find("magnetic_field")
    spec.option.magnetic = numbers(found, 3, "a field 'x y z' in tesla") \
        if found is not None and found.stripped else list(MAGNETIC_FIELD)


def _spherical_coordinates(world: Element) -> SphericalCoordinates:
    found = world.find("spherical_coordinates")
    if found is None:
        return SphericalCoordinates()
    model = found.value("surface_model", "EARTH_WGS84") or "EARTH_WGS84"
    if model != "EARTH_WGS84":
        raise found.find("surface_model").error(
            f"<surface_model> {model}: launcher's navsat knows EARTH_WGS84 only")
    values = []
    for tag in ("latitude_deg", "longitude_deg", "elevation", "heading_deg"):
        text = found.value(tag, "0") or "0"
        try:
            values.append(float(text))
        except ValueError:
            raise found.find(tag).error(f"<spherical_coordinates><{tag}>: expected a number, "
                                        f"got '{text}'") from None
    return SphericalCoordinates(*values)


def _physics(spec: Any, world: Element) -> float | None:
    physics = world.find("physics")
    if physics is None:
        spec.option.timestep = 0.001  # Gazebo's default step
        return None
    step = physics.find("max_step_size")
    if step is not None and step.stripped:
        value = number(step, "a step in seconds")
        if value <= 0:
            raise step.error(f"<max_step_size> must be > 0, got {value:g}")
        spec.option.timestep = value
    else:
        spec.option.timestep = 0.001
    factor = physics.find("real_time_factor")
    if factor is None or not factor.stripped:
        return None
    value = number(factor, "a real-time factor")
    if value < 0:
        raise factor.error(f"<real_time_factor> must be >= 0, got {value:g}")
    return value


def _gravity(spec: Any, world: Element) -> None:
    gravity = world.find("gravity")
    spec.option.gravity = numbers(gravity, 3, "a vector 'x y z'") \
        if gravity is not None and gravity.stripped else [0.0, 0.0, -9.8]


def _scene(spec: Any, world: Element) -> None:
    scene = world.find("scene")
    if scene is None:
        return
    ambient = scene.find("ambient")
    if ambient is not None and ambient.stripped:
        spec.visual.headlight.ambient = numbers(ambient, (3, 4), "a colour 'r g b [a]'")[:3]
    background = scene.find("background")
    if background is not None and background.stripped:
        rgb = numbers(background, (3, 4), "a colour 'r g b [a]'")[:3]
        spec.add_texture(name="background", type=mujoco.mjtTexture.mjTEXTURE_SKYBOX,
                         builtin=mujoco.mjtBuiltin.mjBUILTIN_FLAT, rgb1=rgb, rgb2=rgb,
                         width=32, height=32)


def add_light(spec: Any, light: Element, name: str | None = None,
              pose_element: Element | None = None) -> None:
    """A `<light>`; an `<include>` of one may give it another name and pose."""
    kind = light.get("type", "point")
    pose = parse_pose(pose_element if pose_element is not None else light.find("pose"))
    direction_element = light.find("direction")
    direction = numbers(direction_element, 3, "a direction 'x y z'") \
        if direction_element is not None and direction_element.stripped else [0.0, 0.0, -1.0]
    added = spec.worldbody.add_light(name=name or light.get("name", ""), pos=list(pose.pos),
                                     dir=list(rotate(pose.quat, tuple(direction))))
    added.type = LIGHTS.get(kind, mujoco.mjtLightType.mjLIGHT_POINT)
    for tag, attribute in (("diffuse", "diffuse"), ("specular", "specular")):
        colour = light.find(tag)
        if colour is not None and colour.stripped:
            setattr(added, attribute, numbers(colour, (3, 4), "a colour 'r g b [a]'")[:3])
    added.castshadow = (light.value("cast_shadows", "false") or "").lower() in ("true", "1")
    attenuation = light.find("attenuation")
    if attenuation is not None and kind != "directional":
        added.attenuation = [float(attenuation.value(t, d) or d) for t, d in
                             (("constant", "1"), ("linear", "0"), ("quadratic", "0"))]
        if attenuation.value("range"):
            added.range = float(attenuation.value("range") or 10)
    spot = light.find("spot")
    if spot is not None and kind == "spot" and spot.value("outer_angle"):
        added.cutoff = math.degrees(float(spot.value("outer_angle") or 0.5))


def _models(spec: Any, world: Element, origin: Origin, context: Context) -> list[BuiltModel]:
    built: dict[str, tuple[BuiltModel, Element]] = {}
    for child in world.children:
        if child.tag not in ("model", "include"):
            continue
        if child.tag == "model":
            element, where, placement, static = child, origin, parse_pose(child.find("pose")), None
        else:
            element, where = context.include(child, origin, ("model", "light"))
            if element.tag == "light":  # model://sun: a light, placed and named by the include
                add_light(spec, element, child.value("name"), child.find("pose"))
                continue
            placement = parse_pose(child.find("pose")) if child.find("pose") is not None \
                else parse_pose(element.find("pose"))
            static_text = child.value("static")
            static = static_text.lower() in ("true", "1") if static_text else None
        name = child.value("name") if child.tag == "include" and child.value("name") \
            else element.get("name", "")
        if name in built:
            first = built[name][1].location
            raise child.error(f"two models named '{name}' in world '{world.get('name')}' "
                              f"(the first at {first.file}:{first.line})")
        model = build(spec, element, where, context, f"{name}/", placement, static,
                      name)
        if child.tag == "include":
            model.plugins += plugin_configs(child)
        built[name] = (model, child)
    return [model for model, _ in built.values()]


__all__ = ["SdfWorld", "load_world", "IDENTITY", "Pose"]
