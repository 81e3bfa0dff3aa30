"""`launcher lifecycle nodes | list | get | set`, as `ros2 lifecycle` has them: the nodes that
serve `~/get_state`, their state, the transitions they offer, and a transition asked for by
label (`configure`, `activate`, …) or id. One that is not allowed from the node's state is an
error naming the ones that are."""
