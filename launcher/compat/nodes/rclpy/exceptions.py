"""rclpy.exceptions: what nodes catch, with rclpy's constructors and messages."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any


class NotInitializedException(Exception):
    """Raised when the rclpy implementation is accessed before rclpy.init()."""

    def __init__(self, message: str | None = None) -> None:
        Exception.__init__(self, f"rclpy.init() has not been called. msg:{message}" if message
                           else "rclpy.init() has not been called.")


class NoTypeSupportImportedException(Exception):
    """Raised when there is no type support imported."""

    def __init__(self) -> None:
        Exception.__init__(self, "no type_support imported")


class InvalidHandle(Exception):
    """Raised when an entity is used after it was destroyed."""


class TimerCancelledError(Exception):
    """Raised when a canceled timer is called."""


class NameValidationException(Exception):
    """Raised when a topic name, node name, or namespace are invalid."""

    def __init__(self, name_type: str, name: str, error_msg: str, invalid_index: int) -> None:
        Exception.__init__(self, f"Invalid {name_type}: {error_msg}:\n  '{name}'\n   "
                                 f"{' ' * invalid_index}^")


def _invalid(name_type: str) -> Callable[..., None]:
    """The __init__ of the NameValidationException for one kind of name (rclpy's classes
    keep NameValidationException as their base, so the kind is given here, not by a base)."""
    def __init__(self: NameValidationException, name: str, error_msg: str,
                 invalid_index: int) -> None:
        NameValidationException.__init__(self, name_type, name, error_msg, invalid_index)
    return __init__


class InvalidNamespaceException(NameValidationException):
    """Raised when a namespace is invalid."""

    __init__ = _invalid("namespace")


class InvalidNodeNameException(NameValidationException):
    """Raised when a node name is invalid."""

    __init__ = _invalid("node name")


class InvalidTopicNameException(NameValidationException):
    """Raised when a topic name is invalid."""

    __init__ = _invalid("topic name")


class InvalidServiceNameException(NameValidationException):
    """Raised when a service name is invalid."""

    __init__ = _invalid("service name")


class ParameterException(Exception):
    """Base exception for parameter-related errors."""

    def __init__(self, error_msg: str, parameters: Any) -> None:
        Exception.__init__(self, f"{error_msg}: {parameters}")


class ParameterNotDeclaredException(ParameterException):
    """Raised when handling an undeclared parameter when it is not allowed."""

    def __init__(self, parameters: Any) -> None:
        ParameterException.__init__(self, "Invalid access to undeclared parameter(s)",
                                    parameters)


class ParameterAlreadyDeclaredException(ParameterException):
    """Raised when declaring a parameter that had been declared before."""

    def __init__(self, parameters: Any) -> None:
        ParameterException.__init__(self, "Parameter(s) already declared", parameters)


class InvalidParameterException(ParameterException):
    """Raised when a parameter to be declared has an invalid name."""

    def __init__(self, parameter_name: str) -> None:
        ParameterException.__init__(self, "Invalid parameter name", parameter_name)


class InvalidParameterTypeException(ParameterException):
    """Raised when a parameter is rejected for having an invalid type."""

    def __init__(self, desired_parameter: Any, expected_type: str) -> None:
        kind = getattr(desired_parameter, "type_", "?")
        ParameterException.__init__(
            self, f"Trying to set parameter '{desired_parameter.name}' to "
                  f"'{desired_parameter.value}' of type '{getattr(kind, 'name', kind)}', "
                  f"expecting type '{expected_type}'", desired_parameter.name)


class InvalidParameterValueException(ParameterException):
    """Raised when a parameter is rejected by a user callback or when applying a descriptor."""

    def __init__(self, parameter: str, value: Any, reason: str) -> None:
        ParameterException.__init__(self, f"Invalid parameter value ({value}) for parameter. "
                                          f"Reason: {reason}", parameter)


class ParameterImmutableException(ParameterException):
    """Raised when a read-only parameter is modified."""

    def __init__(self, parameter_name: str) -> None:
        ParameterException.__init__(self, "Attempted to modify read-only parameter",
                                    parameter_name)


class ParameterUninitializedException(ParameterException):
    """Raised when an uninitialized parameter is accessed."""

    def __init__(self, parameter_name: str) -> None:
        ParameterException.__init__(
            self, f"The parameter '{parameter_name}' is not initialized", parameter_name)


class ExternalShutdownException(Exception):
    """The context was shut down (a signal, or another thread) while spinning (rclpy.executors
    offers it; it is here, below the signals and timers that raise it too)."""

    __module__ = "rclpy.executors"  # where rclpy has it: a traceback names it so


class ROSInterruptException(Exception):
    """Raised when an operation is canceled by rclpy shutting down."""

    def __init__(self) -> None:
        Exception.__init__(self, "rclpy.shutdown() has been called")


class RCLError(RuntimeError):
    """Raised when the middleware refuses an operation (rclpy's error from rcl)."""
