"""launch's substitutions for Python launch files: the description layer's substitutions
with launch's constructors (text, substitutions or lists of them, as launch takes them).

A user's own `Substitution` subclass is launch's: it sets its attributes in `__init__` and
answers `perform(context)` (and `describe()`); it may be used wherever these are.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from launcher.description import substitution as _base
from launcher.description.substitution import Text, to_text
from launcher.description.substitutions import command as _command
from launcher.description.substitutions import configuration as _configuration
from launcher.description.substitutions import environment as _environment
from launcher.description.substitutions import expression as _expression
from launcher.description.substitutions import files as _files
from launcher.description.substitutions import logic as _logic
from launcher.description.substitutions import packages as _packages
from launcher.errors import SubstitutionError, SubstitutionFailure  # noqa: F401 (launch.substitutions has it)
from launcher.runtime.context import LaunchContext


class Substitution(_base.Substitution):
    """launch.Substitution: the base of a substitution of the user's own (its attributes
    set freely in `__init__`, unlike launcher's own, which are values)."""

    def __init__(self) -> None:
        object.__setattr__(self, "where", None)

    def __setattr__(self, name: str, value: Any) -> None:
        object.__setattr__(self, name, value)

    def __delattr__(self, name: str) -> None:
        object.__delattr__(self, name)

    __hash__ = object.__hash__

    def __eq__(self, other: object) -> bool:
        return self is other

    def perform(self, context: LaunchContext) -> str:
        raise NotImplementedError(f"{type(self).__name__}.perform(context) is not written")

    def describe(self) -> str:
        return f"{type(self).__name__}()"

    @classmethod
    def parse(cls, data: Any) -> tuple[type, dict[str, Any]]:
        """launch's Substitution.parse: a `$(name …)`'s arguments as the class's keyword
        arguments (none, here: a subclass reads its own)."""
        return cls, {}


def _joined(text: Any) -> str:
    """launch's describe() of a list of substitutions: each one's, joined with ' + '."""
    return " + ".join(f"'{part.text}'" if type(part) is Text else part.describe()
                      for part in text)


def _opt(value: Any) -> Any:
    return None if value is None else to_text(value)


def _set(obj: object, **fields: Any) -> None:
    for name, value in fields.items():
        object.__setattr__(obj, name, value)
    object.__setattr__(obj, "where", None)


class _AnyText(type):
    """Text that launcher's own descriptions hold is a TextSubstitution to user code
    (`isinstance(argument.default_value[0], TextSubstitution)`), as in launch."""

    def __instancecheck__(cls, instance: Any) -> bool:
        return isinstance(instance, Text)


class TextSubstitution(Text, metaclass=_AnyText):
    def __init__(self, *, text: str) -> None:
        _set(self, text=str(text))

    def describe(self) -> str:
        return f"'{self.text}'"


class LaunchConfiguration(_configuration.LaunchConfiguration):
    def __init__(self, variable_name: Any, *, default: Any = None) -> None:
        _set(self, name=to_text(variable_name), default=_opt(default))

    @property
    def variable_name(self) -> Any:
        return list(self.name)

    def describe(self) -> str:
        return f"LaunchConfig({_joined(self.name)})"


class EnvironmentVariable(_environment.EnvironmentVariable):
    def __init__(self, name: Any, *, default_value: Any = None) -> None:
        _set(self, name=to_text(name), default=_opt(default_value))

    def describe(self) -> str:
        return f"EnvVar({_joined(self.name)})"


class Command(_command.Command):
    def __init__(self, command: Any, *, on_stderr: Any = "fail") -> None:
        _set(self, command=to_text(command), on_stderr=to_text(on_stderr))

    def describe(self) -> str:
        return f"Command({_joined(self.command)})"


class PythonExpression(_expression.PythonExpression):
    """A restricted expression (launcher.description.safe_expression), never Python's eval;
    `python_modules` may name math (always there) and the modules it knows."""

    def __init__(self, expression: Any, python_modules: Any = ("math",)) -> None:
        _set(self, expression=to_text(expression), python_modules=python_modules)

    def describe(self) -> str:
        return f"PythonExpr({_joined(self.expression)}, {list(self.python_modules)})"


class FindExecutable(_files.FindExecutable):
    def __init__(self, *, name: Any) -> None:
        _set(self, name=to_text(name))

    def describe(self) -> str:
        return f"FindExec({_joined(self.name)})"


class ThisLaunchFileDir(_files.ThisLaunchFileDir):
    def __init__(self) -> None:
        _set(self)

    def describe(self) -> str:
        return "ThisLaunchFileDir()"


class ThisLaunchFile(_files.ThisLaunchFile):
    def __init__(self) -> None:
        _set(self)

    def describe(self) -> str:
        return "ThisLaunchFile()"


class LaunchLogDir(_files.LogDir):
    def __init__(self) -> None:
        _set(self)

    def describe(self) -> str:
        return "LaunchLogDir()"


class FileContent(_files.FileContent):
    def __init__(self, path: Any) -> None:
        _set(self, path=to_text(path))

    def describe(self) -> str:
        return f"FileContent({_joined(self.path)})"


class PathJoinSubstitution(_files.PathJoinSubstitution):
    def __init__(self, substitutions: Any) -> None:
        super().__init__(list(substitutions))


class PathSubstitution(PathJoinSubstitution):
    """A path that joins with `/` (`PathSubstitution(FindPackageShare('p')) / 'urdf'`)."""

    def __init__(self, path: Any) -> None:
        super().__init__([path])


class AnonName(_configuration.AnonName):
    def __init__(self, name: Any) -> None:
        _set(self, name=to_text(name))

    def describe(self) -> str:
        return f"AnonName({_joined(self.name)})"


class NotSubstitution(_logic.NotSubstitution):
    def __init__(self, value: Any) -> None:
        _set(self, value=to_text(value))


class AndSubstitution(_logic.AndSubstitution):
    def __init__(self, left: Any, right: Any) -> None:
        _set(self, left=to_text(left), right=to_text(right))


class OrSubstitution(_logic.OrSubstitution):
    def __init__(self, left: Any, right: Any) -> None:
        _set(self, left=to_text(left), right=to_text(right))


class AnySubstitution(_logic.AnySubstitution):
    def __init__(self, *args: Any) -> None:
        _set(self, values=tuple(to_text(a) for a in args))


class AllSubstitution(_logic.AllSubstitution):
    def __init__(self, *args: Any) -> None:
        _set(self, values=tuple(to_text(a) for a in args))


class EqualsSubstitution(_logic.EqualsSubstitution):
    def __init__(self, left: Any, right: Any) -> None:
        _set(self, left=_operand(left), right=_operand(right))


class NotEqualsSubstitution(_logic.NotEqualsSubstitution):
    def __init__(self, left: Any, right: Any) -> None:
        _set(self, left=_operand(left), right=_operand(right))


def _operand(value: Any) -> Any:
    """An operand of launch's equals: None is the empty text, a bool true/false."""
    return to_text("" if value is None else value)


class IfElseSubstitution(_logic.IfElseSubstitution):
    def __init__(self, condition: Any, if_value: Any = "", else_value: Any = "") -> None:
        _set(self, condition=to_text(condition), if_value=to_text(if_value),
             else_value=to_text(else_value))


class ForEachVar(_configuration.ForEachVar):
    def __init__(self, name: Any, *, default_value: Any = None) -> None:
        _set(self, name=to_text(name), default=_opt(default_value))


class ForLoopIndex(_configuration.ForLoopIndex):
    def __init__(self, name: Any, **kwargs: Any) -> None:
        _set(self, name=to_text(name))


class StringJoinSubstitution(Substitution):
    """The texts joined with `delimiter`."""

    def __init__(self, substitutions: Iterable[Any], delimiter: Any = "") -> None:
        super().__init__()
        self.substitutions = [to_text(item) for item in substitutions]
        self.delimiter = to_text(delimiter)

    def perform(self, context: LaunchContext) -> str:
        return _base.perform_text(context, self.delimiter).join(
            _base.perform_text(context, item) for item in self.substitutions)

    def describe(self) -> str:
        return f"StringJoin({', '.join(_base.describe_text(s) for s in self.substitutions)})"


class StringStripSubstitution(Substitution):
    """The text without the white space around it."""

    def __init__(self, value: Any) -> None:
        super().__init__()
        self.value = to_text(value)

    def perform(self, context: LaunchContext) -> str:
        return _base.perform_text(context, self.value).strip()


class LocalSubstitution(Substitution):
    """launch.substitutions.LocalSubstitution: a context local, as `event.returncode` or
    `process_name` names it (attribute and item lookups only, never Python's eval)."""

    def __init__(self, expression: str, description: str | None = None) -> None:
        super().__init__()
        self.expression, self.description = expression, description

    def perform(self, context: LaunchContext) -> str:
        import re

        parts = re.findall(r"[A-Za-z_]\w*|\[[^\]]*\]", self.expression)
        if not parts or "".join(p if p.startswith("[") else f".{p}" for p in parts).lstrip(
                ".") != self.expression.replace(" ", ""):
            raise SubstitutionError(f"LocalSubstitution('{self.expression}'): launcher reads "
                                    "a local by names and [index] only")
        value: Any = context.locals
        for part in parts:
            try:
                if part.startswith("["):
                    key = part[1:-1].strip("'\"")
                    value = value[int(key) if key.isdigit() else key]
                elif value is context.locals:
                    value = value[part]
                else:
                    value = getattr(value, part)
            except (KeyError, IndexError, AttributeError, TypeError):
                raise SubstitutionError(f"LocalSubstitution('{self.expression}'): no "
                                        f"'{part}' in the context's locals") from None
        return str(value)

    def describe(self) -> str:
        return self.description or f"LocalVar('{self.expression}')"


class FindPackageShare(_packages.FindPackageShare):
    def __init__(self, package: Any) -> None:
        _set(self, package=to_text(package))


class FindPackagePrefix(_packages.FindPackagePrefix):
    def __init__(self, package: Any) -> None:
        _set(self, package=to_text(package))


FindPackage = FindPackagePrefix


class ExecutableInPackage(_packages.ExecutableInPackage):
    def __init__(self, executable: Any, package: Any) -> None:
        _set(self, executable=to_text(executable), package=to_text(package))


def _truth(context: LaunchContext, text: Any) -> bool:
    from launcher.description.condition import evaluate_condition_text

    return evaluate_condition_text(_base.perform_text(context, text))


class LeftRightLogicalSubstitution(Substitution):
    """`func(left, right)` of two truths, as text (AndSubstitution and OrSubstitution are
    such, in launch)."""

    def __init__(self, func: Any, left: Any, right: Any) -> None:
        super().__init__()
        self.func, self.left, self.right = func, to_text(left), to_text(right)

    def perform(self, context: LaunchContext) -> str:
        value = self.func(_truth(context, self.left), _truth(context, self.right))
        return "true" if value else "false"


class ContainerSubstitution(Substitution):
    """`func(truths)` of any number of truths, as text (AnySubstitution and
    AllSubstitution are such, in launch)."""

    def __init__(self, func: Any, *args: Any) -> None:
        super().__init__()
        self.func, self.args = func, [to_text(arg) for arg in args]

    def perform(self, context: LaunchContext) -> str:
        return "true" if self.func(_truth(context, arg) for arg in self.args) else "false"


class RosParameter(_packages.Parameter):
    """launch_ros.substitutions.Parameter: a parameter set by SetParameter before it."""

    def __init__(self, name: Any, *, default: Any = None) -> None:
        _set(self, name=to_text(name), default=_opt(default))
