"""An independent rmw_zenoh client (the PyPI package zenoh-ros2-sdk) against a running demo.

Its message definitions are written from launcher's type store into a folder of its own (it
would fetch them from GitHub otherwise). It prints one line per check, for the test to read.
Run with ZENOH_SESSION_CONFIG_URI (from `launcher env --zenoh`) and ZENOH_CONFIG_OVERRIDE
giving the same connect endpoints: the SDK puts tcp/127.0.0.1:7447 there itself.
"""

from __future__ import annotations

import os
import sys
import threading
import time
from pathlib import Path

from launcher.bus.types import registry

TYPES = ("nav_msgs/msg/Odometry", "geometry_msgs/msg/Twist", "std_msgs/msg/String")


def write_definitions(folder: Path) -> None:
    """pkg/msg/Name.msg for each type and what it uses (rosbags' concatenated msgdef split)."""
    types = registry()
    for name in TYPES:
        types.ensure(name)
        text, _ = types.store.generate_msgdef(name, ros_version=2)
        chunks = text.split("=" * 80 + "\n")
        definitions = {name: chunks[0]}
        for chunk in chunks[1:]:
            header, _, body = chunk.partition("\n")
            package, message = header.removeprefix("MSG: ").split("/")
            definitions[f"{package}/msg/{message}"] = body
        for full, body in definitions.items():
            package, _, message = full.split("/")
            path = folder / package / "msg" / f"{message}.msg"
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(body)


def main() -> int:
    if os.environ.get("SDK_DEBUG"):  # the SDK's own debug messages, to see what it did
        import logging

        logger = logging.getLogger("zenoh_ros2_sdk")
        logger.setLevel(logging.DEBUG)
        for handler in logger.handlers:
            handler.setLevel(logging.DEBUG)
    folder = Path(sys.argv[1])
    write_definitions(folder)
    from zenoh_ros2_sdk import (
        ROS2Publisher,
        ROS2Subscriber,
        ZenohSession,
        get_message_class,
        get_registry,
        get_topic_names_and_types,
    )
    from zenoh_ros2_sdk.qos import QosDurability, QosProfile

    get_registry(str(folder))
    ZenohSession.get_instance()
    time.sleep(1.0)  # a peer's first queries reach few others: ros2cli spins a while too
    for topic, types in get_topic_names_and_types(timeout=2.0):
        print(f"topic {topic} {','.join(types)}", flush=True)

    odom = threading.Event()
    seen: list[float] = []

    def on_odom(message) -> None:
        seen.append(message.pose.pose.position.x)
        odom.set()

    odometry = ROS2Subscriber("/odom", "nav_msgs/msg/Odometry", on_odom, node_name="sdk_odom")
    print("odom", "yes" if odom.wait(15) else "no", flush=True)

    described = threading.Event()
    text: list[str] = []

    def on_description(message) -> None:
        text.append(message.data)
        described.set()

    latched = ROS2Subscriber("/robot_description", "std_msgs/msg/String", on_description,
                   node_name="sdk_description",
                   qos=QosProfile(durability=QosDurability.TRANSIENT_LOCAL, history_depth=1))
    print("robot_description", "yes" if described.wait(15) and "<robot" in text[0] else "no",
          flush=True)

    publisher = ROS2Publisher("/cmd_vel", "geometry_msgs/msg/Twist", node_name="sdk_driver")
    vector = get_message_class("geometry_msgs/msg/Vector3")
    print("publishing", flush=True)
    deadline = time.monotonic() + float(sys.argv[2])
    while time.monotonic() < deadline:
        publisher.publish(linear=vector(x=0.0, y=0.0, z=0.0),
                          angular=vector(x=0.0, y=0.0, z=1.5))
        time.sleep(0.05)
    for entity in (publisher, latched, odometry):
        entity.close()
    ZenohSession.get_instance().session.close()
    print("done", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
