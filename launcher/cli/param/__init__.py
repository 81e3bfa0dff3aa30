"""`launcher param list | get | set | dump | load NODE …`, through the node's parameter
services, as `ros2 param` has them."""
