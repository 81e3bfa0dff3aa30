"""rospy.impl.masterslave: left out of launcher's rospy (tests/fidelity/left_out.py lists it)."""

raise ImportError("launcher's rospy has no ROS 1 XML-RPC slave API: its nodes meet on "
                  "launcher's Zenoh bus, not through a ROS master",
                  name=__name__)
