"""`launcher rosparam list | get | set | delete | dump | load`: ROS 1's `rosparam` over the
graph's parameter server (bus/graph_parameters.py), which the graph's router hosts and a
ROS 1 launch fills. Names are ROS 1's (`/robot1/robot_description`); a relative one is in
ROS_NAMESPACE (default /)."""
