"""`launcher interface list | show | proto | package | packages`, as `ros2 interface` has
them: the distro's message types (the pinned type store) and the packages' own `.msg` and
`.srv` files."""
