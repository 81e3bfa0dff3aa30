"""The built-in substitutions, one family per module."""
