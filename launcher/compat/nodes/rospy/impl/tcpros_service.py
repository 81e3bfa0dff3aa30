"""rospy.impl.tcpros_service: where rospy defines Service, ServiceProxy and wait_for_service
(launcher's are rospy.service's, on its Zenoh bus), and what the module re-exports. launcher's
rospy does not speak TCPROS, so the TCPROS service transport (ServiceImpl, TCPService,
TCPROSServiceClient, service_connection_handler, …) is not here (tests/fidelity/left_out.py
lists what is left out, and why)."""

from launcher.compat.finder import rest_from_layout
from rospy.core import logdebug, logerr, loginfo, logwarn  # noqa: F401 (it has them)
from rospy.exceptions import (  # noqa: F401
    ROSException,
    ROSInterruptException,
    TransportInitError,
    TransportTerminated,
)
from rospy.impl.registration import get_service_manager  # noqa: F401
from rospy.impl.tcpros_base import DEFAULT_BUFF_SIZE  # noqa: F401
from rospy.names import isstring  # noqa: F401
from rospy.service import (  # noqa: F401
    Service,
    ServiceException,
    ServiceProxy,
    convert_return_to_response,
    wait_for_service,
)

__getattr__ = rest_from_layout(__name__)
