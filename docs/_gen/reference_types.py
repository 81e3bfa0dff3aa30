"""The message and bridge type tables: what the sim speaks, what the bridge converts, and the
message packages built in, from the code's own tables."""

from __future__ import annotations

from md_tables import code, table

from launcher.nodes.conversions import SERVICES, SIM_MESSAGES, SIM_SERVICES, conversions

TITLE = """# Message and bridge types

Generated from the bridge's and the sim's own tables at each build.
"""


def page() -> str:
    parts = [TITLE, "## What the bridge converts\n",
             "A `bridge.yaml` entry (or a `TOPIC@ROS_TYPE@GZ_TYPE` argument) pairs a ROS type "
             "with a sim type of this table; `gz.msgs.X` names the sim's `mujoco_sim/msg/X` "
             "(`Pose_V` is `PoseV`). Where both sides have the same layout the bytes pass "
             "through untouched.\n"]
    rows = []
    for (ros, sim), conversion in conversions().items():
        ways = {(True, True): "both ways", (True, False): "sim → ROS",
                (False, True): "ROS → sim"}[(conversion.to_ros is not None,
                                               conversion.to_sim is not None)]
        rows.append((code(ros), code(_gz(sim)), ways))
    parts.append(table(("ROS type", "sim type", "direction"), rows))
    parts.append("## Services the bridge forwards\n")
    parts.append(table(("ROS service type", "sim service"),
                       [(code(ros), code(sim)) for ros, sim in SERVICES]))
    parts.append("## The sim's own types\n")
    parts.append("Messages (`launcher interface show mujoco_sim/msg/NAME` prints each):\n")
    parts.append(table(("Gazebo's name", "the sim's type"),
                       [(code(_gz(f"mujoco_sim/msg/{m}")), code(f"mujoco_sim/msg/{m}"))
                        for m in SIM_MESSAGES]))
    parts.append("Services, by Gazebo's request and response types:\n")
    parts.append(table(("request", "response", "the sim's service type"),
                       [(code(f"gz.msgs.{req}"), code(f"gz.msgs.{rep}"), code(sim))
                        for (req, rep), sim in SIM_SERVICES.items()]))
    return "\n".join(parts)


def _gz(sim_type: str) -> str:
    short = sim_type.rsplit("/", 1)[-1]
    return "gz.msgs.Pose_V" if short == "PoseV" else f"gz.msgs.{short}"
