"""rospy for launcher's graph: the API of ROS 1's Python client library over launcher's bus,
so ROS 1 node code (the course's publisher.py) runs unchanged where no real rospy is
installed (see launcher/compat/finder.py).

As in rospy, publishers and subscribers may be made before `init_node` (they join the graph
when it is called), callbacks run on a thread of their own while the main thread loops, and
Ctrl-C or SIGTERM shuts the node down: `is_shutdown()` turns true and sleeps raise
ROSInterruptException.

Parameters: `~name` is the node's own parameter (`_name:=value` on the command line sets
it); other names live on the graph's parameter server (bus/graph_parameters.py: the graph's
router hosts it, a ROS 1 launch fills it) when it answers, else on this node under their
resolved name; a name the server lacks is looked up in what the launch gave the node. Message
fields take whole numbers for floats, as ROS 1 did.
"""

from __future__ import annotations

from launcher.compat import rosidl
from rospy.client import (  # noqa: F401
    delete_param,
    get_param,
    get_param_cached,
    get_param_names,
    get_published_topics,
    has_param,
    init_node,
    myargv,
    on_shutdown,
    search_param,
    set_param,
    spin,
    wait_for_message,
)
from rospy.core import (  # noqa: F401
    DEBUG,
    ERROR,
    FATAL,
    INFO,
    WARN,
    core_is_shutdown,
    get_node_uri,
    get_ros_root,
    is_shutdown,
    logdebug,
    logdebug_once,
    logdebug_throttle,
    logdebug_throttle_identical,
    logerr,
    logerr_once,
    logerr_throttle,
    logerr_throttle_identical,
    logerror,
    logfatal,
    logfatal_once,
    logfatal_throttle,
    logfatal_throttle_identical,
    loginfo,
    loginfo_once,
    loginfo_throttle,
    loginfo_throttle_identical,
    logout,
    logwarn,
    logwarn_once,
    logwarn_throttle,
    logwarn_throttle_identical,
    logwarning,
    parse_rosrpc_uri,
    signal_shutdown,
)
from rospy.exceptions import (  # noqa: F401
    ROSException,
    ROSInitException,
    ROSInternalException,
    ROSInterruptException,
    ROSSerializationException,
    ROSTimeMovedBackwardsException,
    ServiceException,
    TransportException,
    TransportInitError,
    TransportTerminated,
)
from rospy.names import get_caller_id, get_name, get_namespace, remap_name, resolve_name  # noqa: F401
from rospy.rostime import Duration, Time, get_rostime, get_time  # noqa: F401
from rospy.service import (  # noqa: F401
    Service,
    ServiceProxy,
    ServiceProxyError,
    wait_for_service,
)
from rospy.timer import Rate, Timer, sleep  # noqa: F401
from rospy.topics import Message, Publisher, SubscribeListener, Subscriber  # noqa: F401

rosidl.lenient()


def __getattr__(name: str) -> object:
    """std_msgs' Header, made when first asked for (rospy re-exports it)."""
    if name == "Header":
        from std_msgs.msg import Header

        globals()["Header"] = Header
        return Header
    raise AttributeError(f"module 'rospy' has no attribute '{name}'")
