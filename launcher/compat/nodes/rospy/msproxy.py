"""rospy.msproxy: left out of launcher's rospy (tests/fidelity/left_out.py lists it)."""

raise ImportError("launcher has no ROS 1 master to proxy (rospy.get_param and the others "
                  "reach launcher's parameter server)",
                  name=__name__)
