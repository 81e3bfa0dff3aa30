"""`launcher node list | info` (shares its graph code with service_command)."""

from launcher.cli.service_command import add_node_parser as add_parser  # noqa: F401
