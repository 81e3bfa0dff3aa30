"""`rospack find | list | list-names | depends1`, as ROS 1's rospack: a package's folder is
where launcher finds it (its source folder, used in place)."""
