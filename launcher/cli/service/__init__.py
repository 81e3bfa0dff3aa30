"""`launcher service list | call | type | find | info`, and `launcher node list | info`, as
`ros2` has them."""
