"""The Python APIs launcher provides for nodes (rclpy, rospy, tf2_ros), from their docstrings:
read from the source (nothing is imported), so the page shows what the code says."""

from __future__ import annotations

import ast
from pathlib import Path

from md_tables import code

NODES = Path(__file__).resolve().parents[2] / "launcher" / "compat" / "nodes"
# the modules whose public surface is documented (tests/unit/test_compat_docs.py keeps it so)
MODULES = ["rclpy/__init__.py", "rclpy/node.py", "rclpy/node_parameters.py",
           "rclpy/executors.py", "rclpy/publisher.py", "rclpy/subscription.py",
           "rclpy/client.py", "rclpy/service.py", "rclpy/timer.py", "rclpy/task.py",
           "rclpy/parameter.py", "rclpy/context.py", "rclpy/utilities.py",
           "rclpy/clock.py", "rclpy/time.py", "rclpy/duration.py", "rclpy/callback_groups.py",
           "rclpy/qos.py", "rclpy/logging.py", "rclpy/guard_condition.py",
           "rclpy/parameter_client.py", "rclpy/lifecycle/node.py",
           "rclpy/lifecycle/managed_entity.py", "rclpy/lifecycle/publisher.py",
           "rclpy/action/server.py", "rclpy/action/client.py", "rclpy/action/graph.py",
           "rospy/client.py", "rospy/core.py", "rospy/rostime.py", "rospy/service.py",
           "rospy/timer.py", "rospy/topics.py", "tf2_ros/buffer.py",
           "tf2_ros/transform_listener.py", "tf2_ros/transform_broadcaster.py",
           "tf2_ros/static_transform_broadcaster.py", "tf2_geometry_msgs/__init__.py",
           "tf/__init__.py", "actionlib/simple_action_client.py",
           "actionlib/simple_action_server.py", "actionlib/action_client.py",
           "actionlib/comm_state_machine.py", "actionlib/action_server.py",
           "actionlib/server_goal_handle.py", "message_filters/__init__.py",
           "cv_bridge/__init__.py", "sensor_msgs_py/point_cloud2.py"]

TITLE = """# Python APIs for nodes

What a node written for ROS imports runs on launcher's graph: rclpy (ROS 2), rospy (ROS 1),
tf2_ros, message_filters, cv_bridge and sensor_msgs_py, with the names, arguments and
defaults of the real libraries (a real one installed in the user's shell wins). Generated from
the source's docstrings at each build.
"""


def page() -> str:
    parts = [TITLE]
    for module in MODULES:
        tree = ast.parse((NODES / module).read_text())
        name = module.removesuffix(".py").removesuffix("/__init__").replace("/", ".")
        parts.append(f"## {code(name)}\n")
        doc = ast.get_docstring(tree)
        if doc:
            parts.append(doc + "\n")
        for node in tree.body:
            if isinstance(node, ast.FunctionDef) and public(node.name):
                parts.append(entry(node, "###"))
            elif isinstance(node, ast.ClassDef) and public(node.name):
                parts.append(f"### {code(node.name)}\n")
                if ast.get_docstring(node):
                    parts.append(ast.get_docstring(node) + "\n")
                parts += [text for f in node.body if (text := member(f))]
    return "\n".join(parts)


def member(node: ast.stmt) -> str:
    """A class member's entry: a public method, or a property made by rclpy's properties.py
    (`name = readonly(path, doc)`, `stored(attr, doc, …)`); "" for anything else."""
    if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
        return entry(node, "####") if public(node.name) else ""
    if isinstance(node, ast.Assign) and isinstance(node.value, ast.Call) and \
            ast.unparse(node.value.func) in ("readonly", "stored") and \
            isinstance(node.targets[0], ast.Name) and public(node.targets[0].id):
        return f"#### {code(node.targets[0].id)}\n\n{ast.literal_eval(node.value.args[1])}\n"
    return ""


def public(name: str) -> bool:
    return not name.startswith("_")


def entry(function: ast.FunctionDef | ast.AsyncFunctionDef, level: str) -> str:
    args = ast.unparse(function.args).replace("self, ", "").removeprefix("self")
    decorators = {ast.unparse(d) for d in function.decorator_list}
    title = function.name if "property" in decorators else f"{function.name}({args})"
    if any(d.endswith(".setter") for d in decorators):
        return ""  # (the property's own entry says it)
    doc = (ast.get_docstring(function) or "").replace(":param ", "- `").replace(":return:",
                                                                                "- returns:")
    lines = [line if not line.startswith("- `") else line.replace(":", "`:", 1)
             for line in doc.splitlines()]
    return f"{level} {code(title)}\n\n" + "\n".join(lines) + "\n"
