"""`launcher control VERB`: ros2controlcli's verbs against a controller manager, printed as
`ros2 control` prints them: list_controllers, list_controller_types,
list_hardware_interfaces, list_hardware_components, load_controller, set_controller_state,
switch_controllers, unload_controller, set_hardware_component_state, cleanup_controller,
reload_controller_libraries and view_controller_chains.

`-c/--controller-manager` names the manager (default /controller_manager). A manager that
is not on the graph is an error after CM_WAIT seconds. view_controller_chains writes
`controller_diagram.gv` and, with graphviz's `dot`, `controller_diagram.gv.pdf` in the
current folder (ROS 2 writes them into the shared /tmp) and prints where.
"""
