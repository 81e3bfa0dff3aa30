"""`launcher node list | info`, as `ros2 node` has them."""
