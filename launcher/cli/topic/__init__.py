"""`launcher topic list | echo | pub | hz | bw | delay | info | type | find`, as `ros2 topic`
has them."""
