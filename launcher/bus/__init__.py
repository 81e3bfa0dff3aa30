"""The bus: Zenoh sessions, ROS 2 names and types (CDR), and the node API."""
