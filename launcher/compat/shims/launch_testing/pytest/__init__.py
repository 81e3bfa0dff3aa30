"""launch_testing.pytest (launcher.compat.testing)."""
