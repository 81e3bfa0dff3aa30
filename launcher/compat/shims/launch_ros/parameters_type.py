"""launch_ros.parameters_type: the types a node's parameters may be given as."""

from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Union

from launcher.api import SomeSubstitutionsType, SomeSubstitutionsType_types_tuple, Substitution
from launcher.api.ros import ParameterDescription, ParameterFile, ParameterValueDescription

SomeParameterFile = Union[SomeSubstitutionsType, Path, ParameterFile]  # noqa: UP007
SomeParameterName = Sequence[Union[Substitution, str]]  # noqa: UP007
SomeParameterValue = Union[ParameterValueDescription, SomeSubstitutionsType,  # noqa: UP007
                           str, int, float, bool, Sequence[Union[str, int, float, bool]]]  # noqa: UP007
SomeParameterValue_types_tuple = (SomeSubstitutionsType_types_tuple + (str, int, float, bool)
                                  + (ParameterValueDescription,))
SomeParametersDict = Mapping[SomeParameterName, Union[SomeParameterValue, Mapping]]  # noqa: UP007
SomeParameters = Sequence[Union[SomeParameterFile, ParameterDescription,  # noqa: UP007
                                SomeParametersDict]]
ParameterName = Sequence[Substitution]
ParameterValue = Union[Sequence[Substitution], ParameterValueDescription]  # noqa: UP007
ParametersDict = dict[tuple[Substitution, ...], ParameterValue]
Parameters = Sequence[Union[ParameterFile, ParametersDict, ParameterDescription]]  # noqa: UP007

__all__ = ["ParameterDescription", "ParameterFile", "ParameterValueDescription",
           "SomeParameterValue_types_tuple", "SomeSubstitutionsType_types_tuple"]


from launcher.compat.finder import rest_from_layout  # noqa: E402

__getattr__ = rest_from_layout(__name__)
