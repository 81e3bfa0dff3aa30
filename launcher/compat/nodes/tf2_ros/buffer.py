"""tf2_ros.Buffer: BufferCore with rclpy's times, timeouts that wait for data to come (on the
node's clock: sim time under use_sim_time), async waits, and `transform` of stamped messages
(tf2_geometry_msgs registers the types)."""

from __future__ import annotations

import threading
import time
from typing import Any

from tf2_ros.buffer_core import (
    BufferCore,
    ConnectivityException,
    ExtrapolationException,
    LookupException,
    TimeoutException,
    TransformException,
)

_CONVERTERS: dict[type, Any] = {}  # message class → do_transform(message, transform)


def register_transform(cls: type, function: Any) -> None:
    """Register a conversion for `Buffer.transform` of another message type
    (tf2_geometry_msgs registers its own).
    """
    _CONVERTERS[cls] = function


def _ns(value: Any) -> int:
    """Nanoseconds of an rclpy Time or Duration, a builtin_interfaces Time, or seconds."""
    if value is None:
        return 0
    if hasattr(value, "nanoseconds"):
        return int(value.nanoseconds)
    if hasattr(value, "to_nsec"):  # rospy's Time and Duration
        return int(value.to_nsec())
    if hasattr(value, "sec"):
        return int(value.sec) * 1_000_000_000 + int(value.nanosec)
    return int(float(value) * 1e9)


class Buffer:
    def __init__(self, cache_time: Any = None, node: Any = None) -> None:
        self.core = BufferCore(_ns(cache_time) or 10 * 1_000_000_000)
        self._node = node
        self._arrived = threading.Condition()
        if node is not None:
            self.core.warn = node.get_logger().warning

    # --- setting -----------------------------------------------------------------------------
    def set_transform(self, transform: Any, authority: str) -> bool:
        """Add a transform (TransformStamped) from `authority`."""
        return self._set(transform, authority, False)

    def set_transform_static(self, transform: Any, authority: str) -> bool:
        """Add a transform that holds at every time."""
        return self._set(transform, authority, True)

    def _set(self, transform: Any, authority: str, static: bool) -> bool:
        t, r = transform.transform.translation, transform.transform.rotation
        try:
            self.core.set_transform(transform.child_frame_id, transform.header.frame_id,
                                    _ns(transform.header.stamp),
                                    ((t.x, t.y, t.z), (r.x, r.y, r.z, r.w)), authority, static)
        except TransformException as exc:
            if self._node is not None:
                self._node.get_logger().error(str(exc))
            return False
        with self._arrived:
            self._arrived.notify_all()
        return True

    def clear(self) -> None:
        """Forget every transform."""
        self.core.clear()

    # --- looking up ----------------------------------------------------------------------
    def lookup_transform(self, target_frame: str, source_frame: str, time: Any,
                         timeout: Any = None) -> Any:
        """The transform from `source_frame` to `target_frame` at `time` (0: the
        latest both have), waiting up to `timeout` for it; LookupException,
        ConnectivityException or ExtrapolationException when there is none.
        """
        stamp = _ns(time)
        pose, at = self._wait(lambda: self.core.lookup(target_frame, source_frame, stamp),
                              timeout)
        return _stamped(pose, at, target_frame, source_frame)

    def lookup_transform_full(self, target_frame: str, target_time: Any, source_frame: str,
                              source_time: Any, fixed_frame: str, timeout: Any = None) -> Any:
        """The transform from `source_frame` at `source_time` to `target_frame`
        at `target_time`, through `fixed_frame`.
        """
        from tf2_ros.buffer_core import multiply

        def both() -> Any:
            fixed_source, _ = self.core.lookup(fixed_frame, source_frame, _ns(source_time))
            target_fixed, _ = self.core.lookup(target_frame, fixed_frame, _ns(target_time))
            return multiply(target_fixed, fixed_source), _ns(target_time)
        pose, at = self._wait(both, timeout)
        return _stamped(pose, at, target_frame, source_frame)

    def can_transform(self, target_frame: str, source_frame: str, time: Any,
                      timeout: Any = None, return_debug_tuple: bool = False) -> Any:
        """Whether lookup_transform would succeed, waiting up to `timeout`."""
        try:
            self.lookup_transform(target_frame, source_frame, time, timeout)
        except TransformException as exc:
            return (False, str(exc)) if return_debug_tuple else False
        return (True, "") if return_debug_tuple else True

    def can_transform_full(self, target_frame: str, target_time: Any, source_frame: str,
                           source_time: Any, fixed_frame: str, timeout: Any = None,
                           return_debug_tuple: bool = False) -> Any:
        """Whether lookup_transform_full would succeed, waiting up to `timeout`."""
        try:
            self.lookup_transform_full(target_frame, target_time, source_frame, source_time,
                                       fixed_frame, timeout)
        except TransformException as exc:
            return (False, str(exc)) if return_debug_tuple else False
        return (True, "") if return_debug_tuple else True

    def transform(self, object_stamped: Any, target_frame: str, timeout: Any = None,
                  new_type: Any = None) -> Any:
        """A stamped message (a point, pose, vector …) expressed in `target_frame`."""
        do = _CONVERTERS.get(type(object_stamped))
        if do is None:
            import tf2_geometry_msgs  # noqa: F401  (registers geometry_msgs' stamped types)

            do = _CONVERTERS.get(type(object_stamped))
        if do is None:
            raise TypeError(f"Type {type(object_stamped).__name__} if not a registered type "
                            "for tf2 transform")
        transform = self.lookup_transform(target_frame, object_stamped.header.frame_id,
                                          object_stamped.header.stamp, timeout)
        return do(object_stamped, transform)

    def wait_for_transform_async(self, target_frame: str, source_frame: str, time: Any) -> Any:
        """A Future completed when the transform can be looked up."""
        from rclpy.task import Future

        future = Future()

        def wait() -> None:
            try:
                self.lookup_transform(target_frame, source_frame, time, 365 * 24 * 3600.0)
                future.set_result(True)
            except TransformException as exc:
                future.set_exception(exc)
        threading.Thread(target=wait, daemon=True).start()
        return future

    def lookup_transform_async(self, target_frame: str, source_frame: str, time: Any) -> Any:
        """A Future of the transform, completed when it can be looked up."""
        from rclpy.task import Future

        future = Future()

        def wait() -> None:
            try:
                future.set_result(self.lookup_transform(target_frame, source_frame, time,
                                                        365 * 24 * 3600.0))
            except TransformException as exc:
                future.set_exception(exc)
        threading.Thread(target=wait, daemon=True).start()
        return future

    def all_frames_as_yaml(self) -> str:
        """Every frame with its parent and times, as tf2's YAML."""
        return self.core.as_yaml()

    def all_frames_as_string(self) -> str:
        """One line a frame naming its parent, as tf2 prints it."""
        return "".join(f"Frame {edge.name} exists with parent {edge.parent}.\n"
                       for edge in self.core.edges())

    def _wait(self, attempt: Any, timeout: Any) -> Any:
        """Try now; with a timeout, try again as transforms come until it passes (the data
        may not be here yet, as tf2_ros waits)."""
        seconds = _ns(timeout) / 1e9
        deadline = time.monotonic() + seconds
        while True:
            try:
                return attempt()
            except (LookupException, ConnectivityException, ExtrapolationException) as exc:
                left = deadline - time.monotonic()
                if left <= 0:
                    if seconds > 0:
                        raise TimeoutException(f"{exc} (after waiting {seconds:g} s)") \
                            from None
                    raise
                with self._arrived:
                    self._arrived.wait(min(left, 0.05))


def _stamped(pose: Any, stamp: int, target: str, source: str) -> Any:
    """A TransformStamped, made as received messages are (rosidl.make: no per-field checks on
    values that are right by construction); lookups are made many times a second."""
    from launcher.compat.rosidl import make

    (x, y, z), (qx, qy, qz, qw) = pose
    header = make("std_msgs/msg/Header", [
        make("builtin_interfaces/msg/Time", [stamp // 1_000_000_000, stamp % 1_000_000_000]),
        target])
    transform = make("geometry_msgs/msg/Transform", [
        make("geometry_msgs/msg/Vector3", [float(x), float(y), float(z)]),
        make("geometry_msgs/msg/Quaternion", [float(qx), float(qy), float(qz), float(qw)])])
    return make("geometry_msgs/msg/TransformStamped", [header, source, transform])
