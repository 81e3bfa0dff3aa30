"""rospy.impl.tcpros_service: left out of launcher's rospy (tests/fidelity/left_out.py lists it)."""

raise ImportError("launcher's rospy does not speak TCPROS: services travel on launcher's "
                  "Zenoh bus (rospy.Service, rospy.ServiceProxy)",
                  name=__name__)
