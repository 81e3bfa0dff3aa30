"""ros2_control: the hardware a URDF's `<ros2_control>` blocks declare, the controller manager
and the controllers users configure, as ros2_control and ros2_controllers behave.

- description.py reads `<ros2_control>` blocks (joints, sensors, interfaces and their params);
- resources.py holds the interfaces' values and who claims each command interface;
- hardware.py is the hardware components (mock_components/GenericSystem here; the sim's own,
  gz_ros2_control's GazeboSimSystem, lives with the sim's plugins and reads MuJoCo's joints);
- controller.py is the base every controller derives from (a lifecycle, a node, interfaces);
- controllers/ holds ros2_controllers' controllers, by type name;
- manager.py is controller_manager: its services, parameters and update cycle.

The manager runs wherever its update is called: inside the sim's step loop (the sim plugin
calls it at `update_rate` in sim time) or in `ros2_control_node` on a wall-clock timer.
"""
