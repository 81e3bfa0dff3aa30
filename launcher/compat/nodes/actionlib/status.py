"""actionlib_msgs/GoalStatus's states, and the names actionlib prints."""

PENDING, ACTIVE, PREEMPTED, SUCCEEDED, ABORTED, REJECTED, PREEMPTING, RECALLING, RECALLED, \
    LOST = range(10)
TERMINAL = (PREEMPTED, SUCCEEDED, ABORTED, REJECTED, RECALLED, LOST)


def message_types(action_spec: object) -> dict[str, type]:
    """{part: class} of an action's ROS 1 messages, from its `<X>Action` class."""
    import importlib

    module_name = action_spec.__module__
    base = action_spec.__name__.removesuffix("Action")
    module = importlib.import_module(module_name)
    return {part: getattr(module, f"{base}{part}")
            for part in ("ActionGoal", "ActionResult", "ActionFeedback", "Goal", "Result",
                         "Feedback")}
