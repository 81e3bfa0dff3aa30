"""imu_sensor_broadcaster/IMUSensorBroadcaster (`~/imu`, sensor_msgs/Imu) and
force_torque_sensor_broadcaster/ForceTorqueSensorBroadcaster (`~/wrench`,
geometry_msgs/WrenchStamped): a ros2_control `<sensor>`'s state interfaces as messages, as
ros2_controllers' do. Parameters: `sensor_name`, `frame_id`; the IMU's
`static_covariance_orientation|angular_velocity|linear_acceleration` (9 numbers each); the
force-torque broadcaster's `interface_names.force.x` … `interface_names.torque.z` instead of
a sensor name (a missing one reads 0)."""

from __future__ import annotations

from launcher.bus.declarations import REQUIRED, Param
from launcher.control.controller import Controller, ControllerError

IMU_INTERFACES = ("orientation.x", "orientation.y", "orientation.z", "orientation.w",
                  "angular_velocity.x", "angular_velocity.y", "angular_velocity.z",
                  "linear_acceleration.x", "linear_acceleration.y", "linear_acceleration.z")
FT_INTERFACES = ("force.x", "force.y", "force.z", "torque.x", "torque.y", "torque.z")


class SensorBroadcaster(Controller):
    """A broadcaster of one ros2_control sensor's state interfaces, `<name>/<interface>` for
    each of INTERFACES in the message's order; SENSOR_PARAMETER is the parameter that names it."""

    SENSOR_PARAMETER = "sensor_name"
    INTERFACES: tuple[str, ...] = ()

    def on_init(self) -> None:
        p = self.read_parameters(self.SENSOR_PARAMETER, "frame_id")
        self.sensor, self.frame_id = p[self.SENSOR_PARAMETER], p["frame_id"]

    def state_interfaces(self) -> list[str]:
        return [f"{self.sensor}/{i}" for i in self.INTERFACES]

    def on_activate(self) -> None:
        self.handles = [self.states[name] for name in self.state_interfaces()]


class IMUSensorBroadcaster(SensorBroadcaster):
    INTERFACES = IMU_INTERFACES
    PARAMETERS = (
        *Controller.PARAMETERS,
        Param("sensor_name", "string", REQUIRED, "the <sensor> of the ros2_control block"),
        Param("frame_id", "string", REQUIRED, "the messages' frame"),
        *(Param(f"static_covariance_{part}", "double_array", [0.0] * 9,
                f"the {part.replace('_', ' ')} covariance (9 numbers)")
          for part in ("orientation", "angular_velocity", "linear_acceleration")),
    )

    def on_configure(self) -> None:
        p = self.read_parameters()
        self.covariances = [p[f"static_covariance_{part}"]
                            for part in ("orientation", "angular_velocity",
                                         "linear_acceleration")]
        self.publisher = self.node.create_publisher("sensor_msgs/msg/Imu", "~/imu", 10)

    def on_cleanup(self) -> None:
        self.publisher.destroy()

    def update(self, time: float, period: float) -> None:
        if not self.publisher.get_subscription_count():
            return
        v = [h.value for h in self.handles]
        make = self.make
        self.publisher.publish(make(
            "sensor_msgs/msg/Imu", header=self.header(time, self.frame_id),
            orientation=make("geometry_msgs/msg/Quaternion", x=v[0], y=v[1], z=v[2], w=v[3]),
            orientation_covariance=self.covariances[0],
            angular_velocity=make("geometry_msgs/msg/Vector3", x=v[4], y=v[5], z=v[6]),
            angular_velocity_covariance=self.covariances[1],
            linear_acceleration=make("geometry_msgs/msg/Vector3", x=v[7], y=v[8], z=v[9]),
            linear_acceleration_covariance=self.covariances[2]))


class ForceTorqueSensorBroadcaster(Controller):
    PARAMETERS = (
        *Controller.PARAMETERS,
        Param("sensor_name", "string", "", "the <sensor> of the ros2_control block"),
        Param("frame_id", "string", REQUIRED, "the messages' frame"),
        *(Param(f"interface_names.{i}", "string", "",
                f"the state interface read as {i}, without a sensor_name")
          for i in FT_INTERFACES),
    )

    def on_init(self) -> None:
        p = self.read_parameters()
        self.sensor, self.frame_id = p["sensor_name"], p["frame_id"]
        named = {i: p[f"interface_names.{i}"] for i in FT_INTERFACES}
        if self.sensor:
            self.names = [f"{self.sensor}/{i}" for i in FT_INTERFACES]
        elif any(named.values()):
            self.names = [named[i] for i in FT_INTERFACES]
        else:
            raise ControllerError(self._at(
                f"controller '{self.name}': give 'sensor_name', or 'interface_names.force.x' "
                f"… 'interface_names.torque.z'"))

    def state_interfaces(self) -> list[str]:
        return [n for n in self.names if n]

    def on_configure(self) -> None:
        self.publisher = self.node.create_publisher("geometry_msgs/msg/WrenchStamped",
                                                    "~/wrench", 10)

    def on_cleanup(self) -> None:
        self.publisher.destroy()

    def on_activate(self) -> None:
        self.handles = [self.states.get(n) if n else None for n in self.names]

    def update(self, time: float, period: float) -> None:
        if not self.publisher.get_subscription_count():
            return
        v = [h.value if h is not None else 0.0 for h in self.handles]
        make = self.make
        self.publisher.publish(make(
            "geometry_msgs/msg/WrenchStamped", header=self.header(time, self.frame_id),
            wrench=make("geometry_msgs/msg/Wrench",
                        force=make("geometry_msgs/msg/Vector3", x=v[0], y=v[1], z=v[2]),
                        torque=make("geometry_msgs/msg/Vector3", x=v[3], y=v[4], z=v[5]))))
