"""rospy.impl.statistics: left out of launcher's rospy (tests/fidelity/left_out.py lists it)."""

raise ImportError("launcher's rospy keeps no per-connection statistics and publishes no "
                  "/statistics",
                  name=__name__)
