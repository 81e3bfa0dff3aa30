"""`rosbag record | play | info`, as ROS 1's rosbag: `.bag` files (ROS 1's format, which
rosbags and ROS 1's own tools read), `record [-a] [-O NAME.bag | -o PREFIX] [--duration D]
TOPIC…`, `play [-r RATE] [-l] [--clock] [--topics …] FILE.bag`, `info FILE.bag`. A bag of
launcher's rosbag2 (MCAP) converts with `launcher bag convert`."""
