"""actionlib.exceptions."""


class ActionException(Exception):
    """An action's goal or state went wrong."""
