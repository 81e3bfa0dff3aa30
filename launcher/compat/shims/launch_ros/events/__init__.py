"""launch_ros.events (launcher.api)."""
