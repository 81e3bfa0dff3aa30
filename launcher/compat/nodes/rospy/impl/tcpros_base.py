"""rospy.impl.tcpros_base: the base of rospy's TCPROS transport, and what the module re-exports
(rospy.core's names, the transport exceptions). launcher's rospy does not speak TCPROS, so
the TCPROS servers and transports (TCPServer, TCPROSServer, TCPROSTransport,
TCPROSTransportProtocol, recv_buff, …) are not here: messages and services travel on
launcher's Zenoh bus (tests/fidelity/left_out.py lists what is left out, and why)."""

from errno import EAGAIN, EWOULDBLOCK  # noqa: F401 (tcpros_base has them)

from launcher.compat.finder import rest_from_layout
from rospy.core import *  # noqa: F403 (tcpros_base re-exports rospy.core)
from rospy.exceptions import (  # noqa: F401 (tcpros_base has them)
    ROSInternalException,
    TransportException,
    TransportInitError,
    TransportTerminated,
)
from rospy.impl.transport import BIDIRECTIONAL, Transport  # noqa: F401
from rospy.service import ServiceException  # noqa: F401

DEFAULT_BUFF_SIZE = 65536  # a connection's receive buffer, as rospy sizes it
TCPROS = "TCPROS"  # the protocol's name in a topic's connection negotiation
python3 = True  # (rospy's flag of the Python it runs on)

__getattr__ = rest_from_layout(__name__)  # (rospy.core's NullHandler, made when asked for)
