"""`launcher action list | info | type | send_goal`, as `ros2 action` has them.

An action is found by its send_goal service (`NAME/_action/send_goal`, typed
`pkg/action/T_SendGoal`): its servers are the nodes serving that, its clients the nodes
calling it. `send_goal` waits for a server (up to `--timeout`, where ros2 waits forever: one
that is not there is an error naming the actions there are), sends the goal, prints the
feedback with `--feedback`, then the result and the status; Ctrl-C cancels the goal first.
"""
