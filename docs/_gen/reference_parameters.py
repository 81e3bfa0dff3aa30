"""The parameters reference: each controller type launcher provides, each built-in node and each
mujoco_ros2_control plugin that declares its parameters as data (bus/declarations.py), as
`ros2 param describe` tells them."""

from __future__ import annotations

import math

from md_tables import code, table

from launcher.bus.declarations import REQUIRED, Param
from launcher.control.controllers import TYPES, controller_class
from launcher.control.manager import PARAMETERS as manager_parameters
from launcher.nodes.foxglove.settings import parameters as foxglove_parameters
from launcher.nodes.joint_state_publisher import PARAMETERS as jsp_parameters
from launcher.nodes.parameter_bridge import PARAMETERS as bridge_parameters
from launcher.nodes.robot_state_publisher import PARAMETERS as rsp_parameters
from launcher.nodes.teleop_twist_keyboard import PARAMETERS as teleop_parameters
from launcher.sim.mujoco_control.ros_plugins import TYPES as PLUGIN_TYPES

TITLE = """# Parameters of controllers and nodes

Generated from the declared parameters at each build. A controller reads them
when it is loaded (its joints and interfaces) and configured (the rest); a value of the wrong
type or out of its bounds is refused at its line in the parameter file, a missing required one
at the controller's block. Every parameter is listed by `ros2 param list` with its default, and
`ros2 param describe` gives its type, description and bounds; a value set on a running
controller takes effect when it is configured again, as with ros2_controllers. A built-in node
reads its parameters when it starts. `{joints}` in a
name stands for each name of the `joints` parameter (`{joint}`: the one joint).
"""

PLUGINS = """## mujoco_ros2_control plugins

The plugins of `mujoco_ros2_control_node`, each made from its `mujoco_plugins.<name>.type`
parameter and reading its own under `mujoco_plugins.{name}.` (the camera and 3D lidar plugins
under a prefix of their own, whatever their name), when the node starts: a wrong value is
refused at its line in the parameter file. `{camera}` stands for each camera of the MJCF,
`{lidar}` for each lidar of its rangefinders (named `<lidar>-NN`), `{sensor}` for each of its
lidar sensors.
"""


# the built-in nodes that declare theirs: (package/executable, its declarations)
NODES = {"foxglove_bridge/foxglove_bridge": foxglove_parameters(),
         "robot_state_publisher/robot_state_publisher": rsp_parameters,
         "joint_state_publisher/joint_state_publisher": jsp_parameters,
         "ros_gz_bridge/parameter_bridge": bridge_parameters,
         "controller_manager/ros2_control_node": manager_parameters,
         "teleop_twist_keyboard/teleop_twist_keyboard": teleop_parameters}


def page() -> str:
    parts = [TITLE, "## Controllers\n"]
    for type_name in sorted(TYPES):
        parts += [f"### {code(type_name)}\n", _table(controller_class(type_name).PARAMETERS)]
    parts.append("## Nodes\n")
    for name, declared in NODES.items():
        parts += [f"### {code(name)}\n", _table(declared)]
    parts.append(PLUGINS)
    for type_name, plugin in PLUGIN_TYPES.items():
        parts += [f"### {code(type_name)}\n", _table(plugin.PARAMETERS, plugin.scope("{name}"))]
    return "\n".join(parts)


def _table(declared: tuple, prefix: str = "") -> str:
    rows = [(code(prefix + p.name), p.type, _default(p.default), _bounds(p), p.description)
            for p in declared]
    return table(("parameter", "type", "default", "bounds", "what it is"), rows)


def _default(value: object) -> str:
    if value is REQUIRED:
        return "required"
    return code(_yaml(value))


def _yaml(value: object) -> str:
    """As a parameter file writes it."""
    if isinstance(value, bool):
        return str(value).lower()
    if isinstance(value, float) and not math.isfinite(value):
        return ".nan" if math.isnan(value) else ("-.inf" if value < 0 else ".inf")
    if isinstance(value, str):
        return f'"{value}"'
    if isinstance(value, list):
        return "[" + ", ".join(_yaml(v) for v in value) + "]"
    return repr(value)


def _bounds(param: Param) -> str:
    low = "" if param.minimum is None else f"{param.minimum:g} ≤ "
    low = low if param.above is None else f"{param.above:g} < "
    high = "" if param.maximum is None else f" ≤ {param.maximum:g}"
    high = high if param.below is None else f" < {param.below:g}"
    return f"{low}value{high}" if low or high else ""
