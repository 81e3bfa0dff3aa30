"""The built-in actions, one concept per module."""
