"""The tf tools' feed (tf2_echo, view_frames, tf2_monitor): /tf and /tf_static into a tf tree,
as tf2_ros's TransformListener fills its buffer."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from launcher.bus.qos import QoS
from launcher.bus.tf_tree import BufferCore, TransformException
from launcher.bus.wire import stamp_nanoseconds


def feed(node: Any, tree: BufferCore, authority: str,
         seen: Callable[[Any, bool], None] | None = None) -> None:
    """Subscribe `node` to /tf and /tf_static (transient local, as tf2 does), each transform
    set in `tree` under `authority` (one tf2 refuses is skipped), and `seen(transform,
    static)` told of each first."""
    def take(static: bool) -> Callable[[Any], None]:
        def on_message(message: Any) -> None:
            for t in message.transforms:
                if seen is not None:
                    seen(t, static)
                v, r = t.transform.translation, t.transform.rotation
                try:
                    tree.set_transform(t.child_frame_id, t.header.frame_id,
                                       stamp_nanoseconds(t.header.stamp),
                                       ((v.x, v.y, v.z), (r.x, r.y, r.z, r.w)),
                                       authority, static)
                except TransformException:
                    continue
        return on_message
    node.create_subscription("tf2_msgs/msg/TFMessage", "/tf", take(False), QoS(depth=100))
    node.create_subscription("tf2_msgs/msg/TFMessage", "/tf_static", take(True),
                             QoS(depth=100, transient_local=True))
