"""rospy.exceptions."""


class ROSException(Exception):
    """Base of rospy's errors."""


class ROSSerializationException(ROSException):
    pass


class ROSInitException(ROSException):
    pass


class ROSInterruptException(ROSException, KeyboardInterrupt):
    """Raised by sleeps and waits when the node is shut down (Ctrl-C, SIGTERM)."""


class ROSTimeMovedBackwardsException(ROSInterruptException):
    def __init__(self, time: float) -> None:
        self.time = time
        super().__init__("ROS time moved backwards")


class ROSInternalException(Exception):
    pass


class ServiceException(ROSException):
    pass


class TransportException(ROSInternalException):
    """A transport (a topic's or service's connection) failed."""


class TransportTerminated(TransportException):
    """The transport was closed."""


class TransportInitError(TransportException):
    """The transport could not be made."""
