"""launch's actions that only Python launch files have: saving and restoring the environment
and the configurations, unsetting a configuration, a coroutine of the user's, and
ExecuteLocal (ExecuteProcess with its process described apart)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, ClassVar

from launcher.description import made_by_code
from launcher.description.action import Action
from launcher.description.actions.executable import ExecuteProcess
from launcher.description.substitution import perform_text, to_text
from launcher.errors import ExecutionError
from launcher.runtime.context import LaunchContext


class _Plain(Action):
    def __init__(self, **kwargs: Any) -> None:
        self.condition, self.where = kwargs.get("condition"), None


class _Step(_Plain):
    """One of the context's own steps: `_step`, a LaunchContext method."""

    _step: ClassVar[Callable[[LaunchContext], None]]

    def execute(self, context: LaunchContext) -> None:
        type(self)._step(context)


class PushEnvironment(_Step):
    """Save the environment of the processes to come (PopEnvironment restores it)."""

    _step = LaunchContext.push_environment


class PopEnvironment(_Step):
    _step = LaunchContext.pop_environment


class PushLaunchConfigurations(_Step):
    """Save the launch configurations (PopLaunchConfigurations restores them)."""

    _step = LaunchContext.push_configurations


class PopLaunchConfigurations(_Step):
    _step = LaunchContext.pop_configurations


class UnsetLaunchConfiguration(_Plain):
    """Forget a launch configuration (from here on in its scope)."""

    def __init__(self, name: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name = to_text(name)

    def execute(self, context: LaunchContext) -> None:
        context.configurations.pop(perform_text(context, self.name), None)


class OpaqueCoroutine(_Plain):
    """Run `coroutine(context, *args, **kwargs)` (or without the context, with
    `ignore_context`) on an asyncio loop of its own beside the launch, until it returns or
    the launch shuts down (then it is cancelled)."""

    def __init__(self, *, coroutine: Callable[..., Any], args: Any = None,
                 kwargs: dict[str, Any] | None = None, ignore_context: bool = False,
                 **left_over_kwargs: Any) -> None:
        super().__init__(**left_over_kwargs)
        self.coroutine, self.args, self.kwargs = coroutine, list(args or ()), dict(kwargs or {})
        self.ignore_context = ignore_context

    def execute(self, context: LaunchContext) -> None:
        arguments = self.args if self.ignore_context else [context, *self.args]
        coroutine = self.coroutine(*arguments, **self.kwargs)
        coroutines = None if context.service is None else context.service.coroutines
        if coroutines is None:  # (a launch only inspected: nothing runs)
            coroutine.close()
            return
        coroutines.run(_located(coroutine))


async def _located(coroutine: Any) -> Any:
    """The coroutine; its failure said at the line of the user's code that raised."""
    try:
        return await coroutine
    except Exception as exc:
        raise ExecutionError(f"OpaqueCoroutine raised {type(exc).__name__}: {exc}",
                             made_by_code.place_of(exc)) from exc


class ExecuteLocal(ExecuteProcess):
    """launch.actions.ExecuteLocal: a process given by its description
    (launch.descriptions.Executable)."""

    def __init__(self, *, process_description: Any, shell: bool = False, **kwargs: Any) -> None:
        executable = process_description
        super().__init__(cmd=executable.cmd, prefix=executable.prefix, name=executable.name,
                         cwd=executable.cwd, env=executable.env,
                         additional_env=executable.additional_env or [], shell=shell,
                         args=executable.arguments, **kwargs)
        self.process_description = process_description


class Executable:
    """launch.descriptions.Executable: what to run (a command line, its environment and
    folder), apart from how ExecuteLocal runs it."""

    def __init__(self, *, cmd: Any, prefix: Any = None, name: Any = None, cwd: Any = None,
                 env: Any = None, additional_env: Any = None, arguments: Any = None) -> None:
        self.cmd, self.prefix, self.name, self.cwd = cmd, prefix, name, cwd
        self.env, self.additional_env, self.arguments = env, additional_env, arguments


class ReplaceEnvironmentVariables(_Plain):
    """The environment of the processes to come becomes `environment` (names and values:
    text or substitutions)."""

    def __init__(self, environment: Any = None, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        pairs = dict(environment or {}).items()
        self.environment = [(to_text(name), to_text(value)) for name, value in pairs]

    def execute(self, context: LaunchContext) -> None:
        replaced = {perform_text(context, name): perform_text(context, value)
                    for name, value in self.environment}
        context.environment.clear()
        context.environment.update(replaced)
