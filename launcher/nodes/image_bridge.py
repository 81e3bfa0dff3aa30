"""`image_bridge TOPIC…`: ros_gz_image's image bridge, each topic's gz.msgs.Image carried to
the ROS side as a sensor_msgs/msg/Image of the same name, one way (the parameter bridge with
those entries: the bytes pass through)."""

from __future__ import annotations

import sys
from typing import Any

from launcher.errors import LaunchError
from launcher.nodes import parameter_bridge, running


def setup(node: Any) -> Any:
    topics = [word for word in node.args if not word.startswith("-")]
    if not topics:
        raise LaunchError("image_bridge: name the image topics to bridge "
                          "(image_bridge /camera …)")
    node.args = [f"{topic}@sensor_msgs/msg/Image[gz.msgs.Image" for topic in topics]
    return parameter_bridge.setup(node)


def main() -> int:
    return running.run_node("image_bridge", setup)


if __name__ == "__main__":
    sys.exit(main())
