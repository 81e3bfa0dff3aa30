"""launcher: a ROS 2-style declarative launch system for simulated robots."""

__version__ = "0.1.0"
