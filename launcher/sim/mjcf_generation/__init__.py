"""mujoco_ros2_control's URDF-to-MJCF converter (`make_mjcf_from_robot_description`,
`robot_description_to_mjcf.sh`): the `<mujoco_inputs>` it reads (inputs.py), where each link
lands (frames.py), the meshes it gathers (meshes.py; COLLADA and convex parts through
apart.py) and the conversion itself (convert.py), done with MuJoCo's own URDF compiler."""
