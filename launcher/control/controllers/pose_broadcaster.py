"""pose_broadcaster/PoseBroadcaster: a pose sensor's state interfaces (`<pose_name>/position.x`
… `orientation.w`) as `~/pose` (geometry_msgs/PoseStamped in `frame_id`) and, with
`tf.enable` (true), as the transform `frame_id` → `tf.child_frame_id` (the pose's name when
empty) on /tf, at most `tf.publish_rate` times a second (0: every update), as
ros2_controllers' does."""

from __future__ import annotations

from launcher.bus.declarations import REQUIRED, Param
from launcher.control.controllers.sensor_broadcasters import SensorBroadcaster


class PoseBroadcaster(SensorBroadcaster):
    SENSOR_PARAMETER = "pose_name"
    INTERFACES = ("position.x", "position.y", "position.z",
                  "orientation.x", "orientation.y", "orientation.z", "orientation.w")
    PARAMETERS = (
        *SensorBroadcaster.PARAMETERS,
        Param("pose_name", "string", REQUIRED, "the pose sensor of the ros2_control block"),
        Param("frame_id", "string", REQUIRED, "the frame the pose is in"),
        Param("tf.enable", "bool", True, "publish the pose as a transform on /tf"),
        Param("tf.child_frame_id", "string", "", "the transform's child (default: pose_name)"),
        Param("tf.publish_rate", "double", 0.0, "transforms a second at most (0: every update)",
              minimum=0.0),
    )

    def on_configure(self) -> None:
        p = self.read_parameters()
        self.tf_enabled = p["tf.enable"]
        self.child = p["tf.child_frame_id"] or self.sensor
        rate = p["tf.publish_rate"]
        self.tf_period = 1.0 / rate if rate > 0 else 0.0
        self.last_tf: float | None = None
        self.publisher = self.node.create_publisher("geometry_msgs/msg/PoseStamped", "~/pose",
                                                    10)
        self.tf_pub = self.node.create_publisher("tf2_msgs/msg/TFMessage", "/tf", 10) \
            if self.tf_enabled else None

    def on_cleanup(self) -> None:
        self.publisher.destroy()
        if self.tf_pub is not None:
            self.tf_pub.destroy()

    def update(self, time: float, period: float) -> None:
        make = self.make
        v = [h.value for h in self.handles]
        if self.publisher.get_subscription_count():
            self.publisher.publish(make(
                "geometry_msgs/msg/PoseStamped", header=self.header(time, self.frame_id),
                pose=make("geometry_msgs/msg/Pose",
                          position=make("geometry_msgs/msg/Point", x=v[0], y=v[1], z=v[2]),
                          orientation=make("geometry_msgs/msg/Quaternion", x=v[3], y=v[4],
                                           z=v[5], w=v[6]))))
        if self.tf_pub is None or not self.tf_pub.get_subscription_count():
            return
        if self.last_tf is not None and time - self.last_tf < self.tf_period - 1e-9:
            return
        self.last_tf = time
        self.tf_pub.publish(make("tf2_msgs/msg/TFMessage", transforms=[make(
            "geometry_msgs/msg/TransformStamped", header=self.header(time, self.frame_id),
            child_frame_id=self.child,
            transform=make("geometry_msgs/msg/Transform",
                           translation=make("geometry_msgs/msg/Vector3", x=v[0], y=v[1],
                                            z=v[2]),
                           rotation=make("geometry_msgs/msg/Quaternion", x=v[3], y=v[4],
                                         z=v[5], w=v[6])))]))
