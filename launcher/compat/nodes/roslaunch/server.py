"""roslaunch.server: left out of launcher's roslaunch (tests/fidelity/left_out.py lists it)."""

raise ImportError("launcher has no ROS 1 XML-RPC launch servers, remote children or master: "
                  "a launch's processes, on this host or another, are supervised by launcher's "
                  "runtime (roslaunch.parent.ROSLaunchParent runs launch files on it)",
                  name=__name__)
