"""rclpy.action: action servers and clients over launcher's bus, in rmw_zenoh's layout.

An action `NAME` of type `pkg/action/T` is three services, `NAME/_action/send_goal`
(`T_SendGoal`), `NAME/_action/cancel_goal` (`action_msgs/srv/CancelGoal`) and
`NAME/_action/get_result` (`T_GetResult`), and two topics, `NAME/_action/feedback`
(`T_FeedbackMessage`) and `NAME/_action/status` (`action_msgs/msg/GoalStatusArray`, latched),
as rcl_action names them; goals are identified by `unique_identifier_msgs/UUID`.
"""

from rclpy.action.client import ActionClient, ClientGoalHandle
from rclpy.action.graph import (
    get_action_client_names_and_types_by_node,
    get_action_names_and_types,
    get_action_server_names_and_types_by_node,
)
from rclpy.action.server import ActionServer, CancelResponse, GoalResponse, ServerGoalHandle

__all__ = ["ActionClient", "ActionServer", "CancelResponse", "ClientGoalHandle", "GoalResponse",
           "ServerGoalHandle", "get_action_client_names_and_types_by_node",
           "get_action_names_and_types", "get_action_server_names_and_types_by_node"]
