"""rclpy.exceptions: what nodes catch."""


class NotInitializedException(Exception):
    def __init__(self, *args: object) -> None:
        Exception.__init__(self, "rclpy.init() has not been called", *args)


class NoTypeSupportImportedException(Exception):
    pass


class InvalidHandle(Exception):
    pass


class NameValidationException(Exception):
    pass


class InvalidNamespaceException(NameValidationException):
    pass


class InvalidNodeNameException(NameValidationException):
    pass


class InvalidTopicNameException(NameValidationException):
    pass


class InvalidServiceNameException(NameValidationException):
    pass


class ParameterException(Exception):
    def __init__(self, error_msg: str, parameters: object = None, *args: object) -> None:
        Exception.__init__(self, f"{error_msg}: {parameters}", *args)


class ParameterNotDeclaredException(ParameterException):
    def __init__(self, parameters: object, *args: object) -> None:
        ParameterException.__init__(self, "Invalid access to undeclared parameter(s)",
                                    parameters, *args)


class ParameterAlreadyDeclaredException(ParameterException):
    def __init__(self, parameters: object, *args: object) -> None:
        ParameterException.__init__(self, "Parameter(s) already declared", parameters, *args)


class InvalidParameterException(ParameterException):
    def __init__(self, parameter: object, *args: object) -> None:
        ParameterException.__init__(self, "Invalid parameter name", parameter, *args)


class InvalidParameterTypeException(ParameterException):
    def __init__(self, desired_parameter: object, expected_type: object, *args: object) -> None:
        ParameterException.__init__(
            self, f"Trying to set parameter to '{getattr(desired_parameter, 'value', '?')}' "
                  f"of type '{getattr(desired_parameter, 'type_', '?')}', expecting type "
                  f"'{expected_type}'", getattr(desired_parameter, "name", "?"), *args)


class InvalidParameterValueException(ParameterException):
    def __init__(self, parameter: object, value: object, reason: str, *args: object) -> None:
        ParameterException.__init__(self, f"Invalid parameter value ({value}) for parameter. "
                                          f"Reason: {reason}", parameter, *args)


class ParameterImmutableException(ParameterException):
    def __init__(self, parameter: object, *args: object) -> None:
        ParameterException.__init__(self, "Attempted to modify read-only parameter",
                                    parameter, *args)


class ParameterUninitializedException(ParameterException):
    def __init__(self, parameter: object, *args: object) -> None:
        ParameterException.__init__(self, "The parameter was not initialized", parameter, *args)


class ROSInterruptException(Exception):
    pass
