"""rospy.msg: left out of launcher's rospy (tests/fidelity/left_out.py lists it)."""

raise ImportError("launcher's rospy has no ROS 1 serialisation (AnyMsg, serialize_message): "
                  "its messages travel on launcher's Zenoh bus, serialised as CDR",
                  name=__name__)
