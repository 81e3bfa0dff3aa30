"""`rosservice list | call | type | info`, as ROS 1's rosservice: the type found on the graph,
the request from YAML or the fields in order (`rosservice call /gazebo/reset_world` needs
none), and the response printed as YAML alone."""
