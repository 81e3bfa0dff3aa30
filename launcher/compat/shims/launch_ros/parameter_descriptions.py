"""launch_ros.parameter_descriptions (launcher.api)."""


from launcher.api import (
    Parameter,
    ParameterFile,
    ParameterValue,
    SomeSubstitutionsType_types_tuple,
)

__all__ = ["Parameter", "ParameterFile", "ParameterValue",
           "SomeSubstitutionsType_types_tuple"]


from launcher.compat.finder import rest_from_layout  # noqa: E402

__getattr__ = rest_from_layout(__name__)
