"""Packages used in place: package.xml, the index, executables, environment hooks, xacro."""
