"""rospy.impl.tcpros: left out of launcher's rospy (tests/fidelity/left_out.py lists it)."""

raise ImportError("launcher's rospy does not speak TCPROS: messages and services travel "
                  "on launcher's Zenoh bus",
                  name=__name__)
