"""`launcher bag record | info | play | list`: rosbag2 bags (MCAP or SQLite), as `ros2 bag`
has them; ROS 1's `rosbag record -O name.bag --duration=60` is taken too, with a note."""
