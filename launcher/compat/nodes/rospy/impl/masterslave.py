"""rospy.impl.masterslave: rospy's ROS 1 XML-RPC node API (the "slave" half of master/slave),
and what the module re-exports (rospy.core's names, the parameter cache, the topic manager).
launcher's nodes meet on its Zenoh bus, not through a ROS master, so the XML-RPC handler
(ROSHandler, apivalidate, is_publishers_list, LOG_API) is not here (tests/fidelity/left_out.py lists
what is left out, and why)."""

from launcher.compat.finder import rest_from_layout
from rospy.core import *  # noqa: F403 (masterslave re-exports rospy.core)
from rospy.impl.paramserver import get_param_server_cache  # noqa: F401 (masterslave has them)
from rospy.impl.registration import get_topic_manager  # noqa: F401
from rospy.impl.validators import ParameterInvalid, non_empty  # noqa: F401

STATUS, MSG, VAL = 0, 1, 2  # the places in a ROS XML-RPC reply's (code, message, value)

__getattr__ = rest_from_layout(__name__)  # (rospy.core's NullHandler, made when asked for)
