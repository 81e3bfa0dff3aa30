"""`rostopic list | echo | pub | hz | bw | info | type`, as ROS 1's rostopic: its flags, its
type names (`std_msgs/String`), `echo /topic/field`, and `pub`'s positional values and its
latching (without `-1` or `-r` it publishes once, latches, and stays until Ctrl-C)."""
