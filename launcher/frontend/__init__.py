"""Frontends: YAML, XML and Python launch files → trees of action descriptions."""
