"""Python cases: launch files and scripts written against launch's and launch_ros's Python
API the way real projects write them (custom actions, substitutions and event handlers, the
launch context, events, opaque functions, a LaunchService run by hand, launch_ros's
parameters, namespaces and lifecycle events).

Besides the probe's starts, a Python case records what its own code saw: `note(...)` (from
PRELUDE, the same text in every case) writes one record per call, and the comparison keeps
their order. Every case's text is PRELUDE (launch's and launch_ros's modules, as launch files import them),
then its own definitions and imports (asyncio, where a case uses it), then
`generate_launch_description()` returning its entities.
"""

from __future__ import annotations

import textwrap
from collections.abc import Iterator
from typing import Any

PRELUDE = '''\
import json
import signal
import os
import sys
import time

import launch
import launch.logging
import launch.utilities
from launch import (Action, Condition, EventHandler, LaunchContext, LaunchDescription,
                    LaunchDescriptionEntity, LaunchIntrospector, LaunchService, Substitution)
from launch.actions import (AppendEnvironmentVariable, DeclareLaunchArgument, EmitEvent,
                            ExecuteLocal, ExecuteProcess, GroupAction, IncludeLaunchDescription,
                            LogInfo, OpaqueCoroutine, OpaqueFunction, PopEnvironment,
                            PopLaunchConfigurations, PushEnvironment, PushLaunchConfigurations,
                            RegisterEventHandler, ResetEnvironment, ResetLaunchConfigurations,
                            SetEnvironmentVariable, SetLaunchConfiguration, Shutdown,
                            TimerAction, UnregisterEventHandler, UnsetEnvironmentVariable,
                            UnsetLaunchConfiguration)
from launch.conditions import (IfCondition, LaunchConfigurationEquals,
                               LaunchConfigurationNotEquals, UnlessCondition)
from launch.event_handlers import (OnExecutionComplete, OnIncludeLaunchDescription,
                                   OnProcessExit, OnProcessIO, OnProcessStart, OnShutdown)
from launch.events import Shutdown as ShutdownEvent
from launch.events.process import ProcessExited, ProcessStarted, ShutdownProcess, SignalProcess
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import (AllSubstitution, AndSubstitution, AnonName,
                                  AnySubstitution, Command, EnvironmentVariable,
                                  EqualsSubstitution, FileContent, FindExecutable,
                                  IfElseSubstitution, LaunchConfiguration, LocalSubstitution,
                                  NotEqualsSubstitution, NotSubstitution, OrSubstitution,
                                  PathJoinSubstitution, PythonExpression, TextSubstitution,
                                  ThisLaunchFile, ThisLaunchFileDir)
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions
from launch_ros.actions import (LifecycleNode, Node, PushROSNamespace, RosTimer, SetParameter,
                                SetParametersFromFile, SetRemap, SetROSLogDir, SetUseSimTime)
from launch_ros.descriptions import ParameterFile, ParameterValue
from launch_ros.event_handlers import OnStateTransition
from launch_ros.events.lifecycle import ChangeState, matches_node_name
from launch_ros.substitutions import ExecutableInPackage, FindPackagePrefix, FindPackageShare
import lifecycle_msgs.msg

HERE = os.path.dirname(os.path.abspath(__file__))


def note(*words):
    """Record what the launch file saw, in order (the corpus compares these records)."""
    path = os.path.join(os.environ["PROBE_OUT"], f"{time.monotonic_ns()}-{os.getpid()}-note.json")
    with open(path + ".part", "w", encoding="utf-8") as stream:
        json.dump({"note": [str(word) for word in words]}, stream)
    os.rename(path + ".part", path)


def performed(context, value):
    if isinstance(value, str):
        return value
    return perform_substitutions(context, normalize_to_list_of_substitutions(value))


def noted(*words, **kwargs):
    """An action that notes `words`, their substitutions performed, when it runs."""
    return OpaqueFunction(function=lambda context: note(*[performed(context, word)
                                                          for word in words]), **kwargs)


def probe(name="n", **kwargs):
    return Node(package="probe", executable="probe", name=name, **kwargs)


def probe_cmd(*args):
    return [ExecutableInPackage("probe", "probe"), *args]

'''


def _launch_file(definitions: str, entities: str) -> str:
    body = textwrap.indent(textwrap.dedent(entities).strip("\n"), " " * 8)
    return (PRELUDE + textwrap.dedent(definitions).strip("\n") + "\n\n\n"
            "def generate_launch_description():\n    return LaunchDescription([\n"
            f"{body}\n    ])\n")


def py(name: str, entities: str, definitions: str = "", **extra: Any) -> dict[str, Any]:
    """A launch file, run by `ros2 launch` (`launcher launch`)."""
    files = {"main.launch.py": _launch_file(definitions, entities), **extra.pop("files", {})}
    return {"name": f"ros2/python/{name}", "files": files, "main": "main.launch.py", **extra}


def script(name: str, text: str, **extra: Any) -> dict[str, Any]:
    """A script of launch's API, run by python (as launch's own examples run)."""
    files = {"main.py": PRELUDE + textwrap.dedent(text).strip("\n") + "\n",
             **extra.pop("files", {})}
    return {"name": f"ros2/python/{name}", "files": files, "main": "main.py", **extra}


def actions() -> Iterator[dict[str, Any]]:
    """Custom Action subclasses: execute(context) returning entities, or nothing."""
    yield py("action/execute-returns-entities", "Spawn(),", """
        class Spawn(Action):
            def execute(self, context):
                return [probe()]
    """)
    yield py("action/execute-returns-none", "Mark(), noted('after'),", """
        class Mark(Action):
            def execute(self, context):
                note('mark ran')
    """)
    yield py("action/execute-reads-argument",
             "DeclareLaunchArgument('who', default_value='world'), Read(),", """
        class Read(Action):
            def execute(self, context):
                note('who', context.launch_configurations['who'])
    """)
    yield py("action/execute-reads-argument-given",
             "DeclareLaunchArgument('who', default_value='world'), Read(),", """
        class Read(Action):
            def execute(self, context):
                note('who', context.launch_configurations['who'])
    """, args=("who:=you",))
    yield py("action/condition-false", "Mark(condition=IfCondition('false')), noted('end'),", """
        class Mark(Action):
            def execute(self, context):
                note('mark ran')
    """)
    yield py("action/condition-true", "Mark(condition=IfCondition('true')), noted('end'),", """
        class Mark(Action):
            def execute(self, context):
                note('mark ran')
    """)
    yield py("action/nested", "Outer(),", """
        class Inner(Action):
            def execute(self, context):
                note('inner')
                return [probe('inner')]

        class Outer(Action):
            def execute(self, context):
                note('outer')
                return [Inner(), noted('after inner')]
    """)
    yield py("action/order", "Mark('a'), Mark('b'), Mark('c'),", """
        class Mark(Action):
            def __init__(self, label, **kwargs):
                super().__init__(**kwargs)
                self.label = label

            def execute(self, context):
                note(self.label)
    """)
    yield py("action/returns-launch-description", "Spawn(),", """
        class Spawn(Action):
            def execute(self, context):
                return [LaunchDescription([noted('inside'), probe()])]
    """)
    yield py("action/execute-raises", "Broken(), probe(),", """
        class Broken(Action):
            def execute(self, context):
                raise RuntimeError('broken on purpose')
    """)
    yield py("action/sub-entities", "Mark(),", """
        class Mark(Action):
            def execute(self, context):
                note('sub-entities', len(self.get_sub_entities()), self.condition is None)
    """)
    yield py("action/sets-configuration", "Set(), probe(arguments=[LaunchConfiguration('x')]),",
             """
        class Set(Action):
            def execute(self, context):
                context.launch_configurations['x'] = 'from-action'
    """)
    yield py("action/entity-subclass", "Entity(),", """
        class Entity(LaunchDescriptionEntity):
            def visit(self, context):
                note('visited')
                return [probe()]
    """)


def context_api() -> Iterator[dict[str, Any]]:
    """LaunchContext as launch files use it."""
    def opaque(name: str, function: str, entities: str = "", **extra: Any):
        return py(name, f"{entities}OpaqueFunction(function=look),", function, **extra)

    yield opaque("context/configuration-default", """
        def look(context):
            note(context.launch_configurations.get('missing', 'default'))
    """)
    yield opaque("context/configurations-sorted", """
        def look(context):
            note(*sorted(context.launch_configurations.items()))
    """, "DeclareLaunchArgument('b', default_value='2'), DeclareLaunchArgument('a', "
         "default_value='1'), ", args=("b:=3",))
    yield opaque("context/perform-substitution", """
        def look(context):
            note(context.perform_substitution(LaunchConfiguration('x')))
    """, "SetLaunchConfiguration('x', 'value'), ")
    yield opaque("context/environment-read", """
        def look(context):
            note(context.environment.get('PROBE_V'), 'PROBE_NONE' in context.environment)
    """, env={"PROBE_V": "shell"})
    yield opaque("context/environment-write", """
        def look(context):
            context.environment['PROBE_W'] = 'written'
            return [probe()]
    """)
    yield opaque("context/environment-after-set-env", """
        def look(context):
            note(context.environment.get('PROBE_S'), os.environ.get('PROBE_S'))
    """, "SetEnvironmentVariable('PROBE_S', 'set'), ")
    yield opaque("context/locals-extend", """
        def look(context):
            context.extend_locals({'mine': 'kept'})
            note(context.locals.mine, context.get_locals_as_dict()['mine'])
    """)
    yield opaque("context/locals-launch-file", """
        def look(context):
            note(context.locals.current_launch_file_path,
                 context.locals.current_launch_file_directory)
    """)
    yield opaque("context/argv", """
        def look(context):
            note(*context.argv)
    """, args=("a:=1", "b:=2"))
    yield opaque("context/is-shutdown", """
        def look(context):
            note(context.is_shutdown)
    """)
    yield opaque("context/asyncio-loop", """
        import asyncio

        def look(context):
            note(isinstance(context.asyncio_loop, asyncio.AbstractEventLoop))
    """)
    yield opaque("context/globals", """
        def look(context):
            context.extend_globals({'g': 1})
            note(context.locals.g)
    """)
    yield py("context/locals-scoped-by-group",
             "GroupAction([OpaqueFunction(function=inner)]), OpaqueFunction(function=outer),", """
        def inner(context):
            context.extend_locals({'mine': 'inner'})
            note('inner', context.locals.mine)

        def outer(context):
            note('outer', 'mine' in context.get_locals_as_dict())
    """)
    yield py("context/configuration-scoped-by-group",
             "GroupAction([SetLaunchConfiguration('x', 'in')]), noted('x', "
             "LaunchConfiguration('x', default='out')),")
    yield py("context/configuration-group-not-scoped",
             "GroupAction([SetLaunchConfiguration('x', 'in')], scoped=False), noted('x', "
             "LaunchConfiguration('x', default='out')),")
    yield py("context/push-pop-configurations",
             "SetLaunchConfiguration('x', '1'), PushLaunchConfigurations(), "
             "SetLaunchConfiguration('x', '2'), noted('inside', LaunchConfiguration('x')), "
             "PopLaunchConfigurations(), noted('after', LaunchConfiguration('x')),")
    yield py("context/reset-configurations",
             "SetLaunchConfiguration('x', '1'), SetLaunchConfiguration('y', '2'), "
             "ResetLaunchConfigurations({'y': LaunchConfiguration('y')}), "
             "noted('x', LaunchConfiguration('x', default='unset'), 'y', "
             "LaunchConfiguration('y')),")
    yield py("context/unset-configuration",
             "SetLaunchConfiguration('x', '1'), UnsetLaunchConfiguration('x'), "
             "noted(LaunchConfiguration('x', default='gone')),")
    yield py("context/set-configuration-substituted",
             "SetLaunchConfiguration('a', 'one'), SetLaunchConfiguration('b', "
             "[LaunchConfiguration('a'), '-two']), noted(LaunchConfiguration('b')),")
    yield py("context/push-pop-environment",
             "PushEnvironment(), SetEnvironmentVariable('PROBE_E', 'pushed'), probe('a'), "
             "PopEnvironment(), probe('b'),")
    yield py("context/reset-environment",
             "SetEnvironmentVariable('PROBE_E', 'set'), ResetEnvironment(), probe(),",
             env={"PROBE_V": "shell"})


SUBSTITUTIONS = {
    "text": "TextSubstitution(text='plain')",
    "configuration": "LaunchConfiguration('x')",
    "configuration-default": "LaunchConfiguration('unset', default='fallback')",
    "configuration-default-list": "LaunchConfiguration('unset', default=['a', 'b'])",
    "configuration-missing": "LaunchConfiguration('unset')",
    "env": "EnvironmentVariable('PROBE_V')",
    "env-default": "EnvironmentVariable('PROBE_NONE', default_value='dflt')",
    "env-missing": "EnvironmentVariable('PROBE_NONE')",
    "find-executable": "FindExecutable(name='sh')",
    "find-executable-missing": "FindExecutable(name='no-such-program')",
    "python-expression": "PythonExpression(['1 + ', LaunchConfiguration('x2')])",
    "python-expression-string": "PythonExpression([\"'a' * 3\"])",
    "python-expression-math": "PythonExpression(['math.floor(2.7)'])",
    "python-expression-modules": "PythonExpression(['os.sep'], python_modules=['os'])",
    "python-expression-bad": "PythonExpression(['1 +'])",
    "command": "Command(['echo ', LaunchConfiguration('x')])",
    "command-fails": "Command('false')",
    "command-stderr-ignore": "Command('sh -c \"echo out; echo err >&2\"', on_stderr='ignore')",
    "command-stderr-capture": "Command('sh -c \"echo out; echo err >&2\"', "
                              "on_stderr='capture')",
    "this-launch-file": "ThisLaunchFile()",
    "this-launch-file-dir": "ThisLaunchFileDir()",
    "path-join": "PathJoinSubstitution(['a', LaunchConfiguration('x'), 'c.txt'])",
    "path-join-absolute": "PathJoinSubstitution([ThisLaunchFileDir(), 'sub', 'f'])",
    "equals-true": "EqualsSubstitution('a', 'a')",
    "equals-false": "EqualsSubstitution('a', 'b')",
    "equals-numbers": "EqualsSubstitution('1', '1.0')",
    "equals-bools": "EqualsSubstitution('true', 'True')",
    "equals-none": "EqualsSubstitution(None, '')",
    "equals-configuration": "EqualsSubstitution(LaunchConfiguration('x'), 'value')",
    "not-equals": "NotEqualsSubstitution('a', 'b')",
    "not-equals-same": "NotEqualsSubstitution('2', '2')",
    "and": "AndSubstitution('true', 'false')",
    "and-true": "AndSubstitution('1', 'True')",
    "or": "OrSubstitution('false', 'true')",
    "or-false": "OrSubstitution('0', 'false')",
    "not": "NotSubstitution('true')",
    "not-zero": "NotSubstitution('0')",
    "not-bad": "NotSubstitution('maybe')",
    "all": "AllSubstitution('true', '1', 'True')",
    "all-one-false": "AllSubstitution('true', 'false')",
    "all-none": "AllSubstitution()",
    "any": "AnySubstitution('false', '1')",
    "any-none": "AnySubstitution()",
    "if-else-true": "IfElseSubstitution('true', 'yes', 'no')",
    "if-else-false": "IfElseSubstitution(LaunchConfiguration('f'), 'yes', 'no')",
    "if-else-bad": "IfElseSubstitution('perhaps', 'yes', 'no')",
    "file-content": "FileContent(PathJoinSubstitution([ThisLaunchFileDir(), 'data.txt']))",
    "file-content-missing": "FileContent('/nonexistent/data.txt')",
    "anon-name-stable": "PythonExpression(["
                        "'\\'', AnonName('a'), '\\' == \\'', AnonName('a'), '\\''])",
    "find-package-share": "FindPackageShare('probe')",
    "find-package-prefix": "FindPackagePrefix('probe')",
    "find-package-missing": "FindPackageShare('no_such_package')",
    "executable-in-package": "ExecutableInPackage('probe', 'probe')",
    "executable-in-package-missing": "ExecutableInPackage('nothing', 'probe')",
    "list": "['a', LaunchConfiguration('x'), 'c']",
}


def substitutions() -> Iterator[dict[str, Any]]:
    for label, expression in SUBSTITUTIONS.items():
        yield py(f"substitution/{label}",
                 "SetLaunchConfiguration('x', 'value'), SetLaunchConfiguration('x2', '2'), "
                 f"SetLaunchConfiguration('f', 'false'), noted({expression}),",
                 files={"data.txt": "the file's text\n"}, env={"PROBE_V": "shell"})
    yield py("substitution/custom", "noted(Shout('hi')), SetLaunchConfiguration('x', 'there'), "
             "noted(Shout(LaunchConfiguration('x'))),",
             """
        class Shout(Substitution):
            def __init__(self, text):
                super().__init__()
                self.text = normalize_to_list_of_substitutions(text)

            def describe(self):
                return 'Shout(...)'

            def perform(self, context):
                return perform_substitutions(context, self.text).upper() + '!'
    """)
    yield py("substitution/custom-describe", "noted(Shout().describe(), "
             "str(len(LaunchConfiguration('x').describe()) > 0)),", """
        class Shout(Substitution):
            def describe(self):
                return 'shouting'

            def perform(self, context):
                return 'HI'
    """)
    yield py("substitution/custom-in-node-arguments", "probe(arguments=[Twice('ab')]),", """
        class Twice(Substitution):
            def __init__(self, text):
                super().__init__()
                self.text = text

            def perform(self, context):
                return self.text * 2
    """)
    yield py("substitution/configuration-in-node-name",
             "DeclareLaunchArgument('who', default_value='robot'), "
             "probe(name=LaunchConfiguration('who')),", args=("who:=other",))
    yield py("substitution/concatenation-in-arguments",
             "SetLaunchConfiguration('x', 'v'), "
             "probe(arguments=['a', ['pre-', LaunchConfiguration('x')], 'c']),")


CONDITIONS = {
    "if-true": "IfCondition('true')",
    "if-True": "IfCondition('True')",
    "if-one": "IfCondition('1')",
    "if-false": "IfCondition('false')",
    "if-zero": "IfCondition('0')",
    "if-bad": "IfCondition('yes')",
    "if-configuration": "IfCondition(LaunchConfiguration('t'))",
    "if-expression": "IfCondition(PythonExpression([LaunchConfiguration('n'), ' > 1']))",
    "if-and": "IfCondition(AndSubstitution(LaunchConfiguration('t'), 'false'))",
    "if-equals": "IfCondition(EqualsSubstitution(LaunchConfiguration('n'), '3'))",
    "unless-true": "UnlessCondition('true')",
    "unless-false": "UnlessCondition(LaunchConfiguration('t2'))",
    "configuration-equals": "LaunchConfigurationEquals('n', '3')",
    "configuration-equals-other": "LaunchConfigurationEquals('n', '4')",
    "configuration-equals-none": "LaunchConfigurationEquals('unset', None)",
    "configuration-not-equals": "LaunchConfigurationNotEquals('n', '4')",
    "configuration-not-equals-unset": "LaunchConfigurationNotEquals('unset', 'x')",
    "custom-predicate": "Condition(predicate=lambda context: "
                        "context.launch_configurations['n'] == '3')",
}


def conditions() -> Iterator[dict[str, Any]]:
    for label, expression in CONDITIONS.items():
        yield py(f"condition/{label}",
                 "SetLaunchConfiguration('t', 'true'), SetLaunchConfiguration('t2', 'false'), "
                 f"SetLaunchConfiguration('n', '3'), probe(condition={expression}), "
                 "noted('end'),")
    yield py("condition/on-group", "GroupAction([probe('a'), probe('b')], "
             "condition=UnlessCondition('true')), probe('c'),")
    yield py("condition/on-argument", "DeclareLaunchArgument('x', default_value='d', "
             "condition=IfCondition('false')), noted(LaunchConfiguration('x', default='none')),")
    yield py("condition/on-include", "IncludeLaunchDescription(PythonLaunchDescriptionSource("
             "[ThisLaunchFileDir(), '/inner.launch.py']), condition=IfCondition('false')), "
             "noted('end'),", files={"inner.launch.py": _launch_file("", "noted('inner'),")})
    yield py("condition/custom-subclass", "probe(condition=Never()), probe('m'),", """
        class Never(Condition):
            def __init__(self):
                super().__init__(predicate=lambda context: False)
    """)


def events() -> Iterator[dict[str, Any]]:
    """Event handlers, the events' fields, and Shutdown. (A process is stopped with SIGINT
    only once it has had time to start: one stopped while Python starts exits 1, not -2.)"""
    yield py("event/on-process-start", """
        RegisterEventHandler(OnProcessStart(target_action=first, on_start=[noted('started'),
                                                                             probe('second')])),
        first,
    """, "first = probe('first')")
    yield py("event/on-process-exit-returncode", """
        RegisterEventHandler(OnProcessExit(target_action=first, on_exit=[
            noted('exit', LocalSubstitution('event.returncode'))])),
        first,
    """, "first = probe('first', additional_env={'PROBE_EXIT': '3'})")
    yield py("event/on-process-exit-function", """
        RegisterEventHandler(OnProcessExit(target_action=first, on_exit=seen)),
        first,
    """, """
        first = probe('first')

        def seen(event, context):
            note(type(event).__name__, event.returncode, event.action is first,
                 isinstance(event.pid, int), event.cmd[-3:])
            return [probe('after')]
    """)
    yield py("event/on-process-start-fields", """
        RegisterEventHandler(OnProcessStart(target_action=first, on_start=seen)),
        first,
    """, """
        first = ExecuteProcess(cmd=probe_cmd('x'), name='named', cwd='/',
                               additional_env={'PROBE_A': '1'})

        def seen(event, context):
            note(type(event).__name__, event.name, event.cwd, event.cmd[1:],
                 event.env.get('PROBE_A'), event.action is first)
    """)
    yield py("event/on-process-exit-any", """
        RegisterEventHandler(OnProcessExit(on_exit=lambda event, context: note(
            'exit', event.action.name, event.returncode))),
        probe('a'),
    """)
    yield py("event/on-process-io", """
        RegisterEventHandler(OnProcessIO(target_action=talker, on_stdout=heard)),
        talker,
    """, """
        talker = ExecuteProcess(cmd=['sh', '-c', 'echo one; echo two'], name='talker')

        def heard(event):
            note(type(event).__name__, event.text.decode().split())
    """)
    yield py("event/on-process-io-stderr", """
        RegisterEventHandler(OnProcessIO(target_action=talker, on_stderr=heard)),
        talker,
    """, """
        talker = ExecuteProcess(cmd=['sh', '-c', 'echo oops >&2'], name='talker')

        def heard(event):
            note(type(event).__name__, event.text.decode().strip())
    """)
    yield py("event/shutdown-event", """
        RegisterEventHandler(OnShutdown(on_shutdown=lambda event, context: note(
            'shutdown', event.reason, event.due_to_sigint))),
        EmitEvent(event=ShutdownEvent(reason='all done')),
        probe(),
    """)
    yield py("event/shutdown-action", """
        RegisterEventHandler(OnShutdown(on_shutdown=[noted('shutting down',
            LocalSubstitution('event.reason'))])),
        Shutdown(reason='stopping'),
    """)
    yield py("event/shutdown-after-exit", """
        RegisterEventHandler(OnProcessExit(target_action=first, on_exit=[
            EmitEvent(event=ShutdownEvent(reason='first ended'))])),
        RegisterEventHandler(OnShutdown(on_shutdown=[noted(
            'shutdown', LocalSubstitution('event.reason'))])),
        first,
    """, "first = probe('first')")
    yield py("event/shutdown-stops-sleeper", """
        RegisterEventHandler(OnProcessStart(target_action=sleeper, on_start=[
            TimerAction(period=1.5, actions=[Shutdown(reason='go')])])),
        RegisterEventHandler(OnProcessExit(target_action=sleeper, on_exit=lambda event, ctx:
            note('exit', event.returncode))),
        sleeper,
    """, "sleeper = probe('sleeper', additional_env={'PROBE_SLEEP': '30'})")
    yield py("event/signal-process", """
        RegisterEventHandler(OnProcessStart(target_action=sleeper, on_start=[
            EmitEvent(event=SignalProcess(signal_number=signal.SIGTERM,
                                          process_matcher=lambda action: action is sleeper))])),
        RegisterEventHandler(OnProcessExit(target_action=sleeper, on_exit=lambda event, ctx:
            note('exit', event.returncode))),
        sleeper,
    """, "sleeper = probe('sleeper', additional_env={'PROBE_SLEEP': '30'})")
    yield py("event/shutdown-process", """
        RegisterEventHandler(OnProcessStart(target_action=sleeper, on_start=[
            TimerAction(period=1.5, actions=[EmitEvent(event=ShutdownProcess(
                process_matcher=lambda action: action is sleeper))])])),
        RegisterEventHandler(OnProcessExit(target_action=sleeper, on_exit=lambda event, ctx:
            note('exit', event.returncode))),
        sleeper,
    """, "sleeper = probe('sleeper', additional_env={'PROBE_SLEEP': '30'})")
    yield py("event/execution-complete", """
        RegisterEventHandler(OnExecutionComplete(target_action=mark, on_completion=[
            noted('complete')])),
        mark,
    """, "mark = noted('mark')")
    yield py("event/execution-complete-function", """
        RegisterEventHandler(OnExecutionComplete(target_action=mark, on_completion=lambda event,
            context: note(type(event).__name__, event.action is mark))),
        mark,
    """, "mark = LogInfo(msg='hello')")
    yield py("event/include-event", """
        EmitEvent(event=launch.events.IncludeLaunchDescription(LaunchDescription([
            noted('included'), probe()]))),
        noted('emitted'),
    """, "import launch.events")
    yield py("event/on-include-handler", """
        RegisterEventHandler(OnIncludeLaunchDescription()),
        EmitEvent(event=launch.events.IncludeLaunchDescription(LaunchDescription([
            noted('included')]))),
    """, "import launch.events")
    yield py("event/handler-once", """
        RegisterEventHandler(OnProcessExit(on_exit=lambda event, context: note(
            'once', event.action.name), handle_once=True)),
        probe('a'),
        TimerAction(period=1.0, actions=[probe('b')]),
    """)
    yield py("event/unregister", """
        handler,
        UnregisterEventHandler(handler.event_handler),
        probe(),
        TimerAction(period=0.5, actions=[noted('end')]),
    """, """
        handler = RegisterEventHandler(OnProcessStart(on_start=[noted('should not')]))
    """)
    yield py("event/handler-registers-handler", """
        RegisterEventHandler(OnProcessStart(target_action=first, on_start=[
            RegisterEventHandler(OnProcessExit(target_action=first, on_exit=[
                noted('exit seen')]))])),
        first,
    """, "first = probe('first', additional_env={'PROBE_SLEEP': '0.5'})")
    yield py("event/custom-event-handler", """
        RegisterEventHandler(Every(matcher=lambda event: isinstance(event, ProcessStarted),
                                   entities=[noted('custom handler')])),
        probe(),
    """, """
        class Every(EventHandler):
            pass
    """)
    yield py("event/custom-event", """
        RegisterEventHandler(EventHandler(matcher=lambda event: isinstance(event, Ping),
                                          entities=[noted('pong', LocalSubstitution(
                                              'event.payload'))])),
        EmitEvent(event=Ping('hello')),
    """, """
        class Ping(launch.Event):
            name = 'corpus.Ping'

            def __init__(self, payload):
                super().__init__()
                self.payload = payload
    """)
    yield py("event/sequence", """
        RegisterEventHandler(OnProcessExit(target_action=a, on_exit=[noted('a done'), b])),
        RegisterEventHandler(OnProcessExit(target_action=b, on_exit=[noted('b done'), c])),
        a,
    """, """
        a = probe('a')
        b = probe('b')
        c = probe('c')
    """)
    yield py("event/timer", """
        TimerAction(period=0.6, actions=[noted('late')]),
        TimerAction(period=0.2, actions=[noted('early')]),
        noted('now'),
    """)
    yield py("event/timer-substituted-period", """
        SetLaunchConfiguration('p', '0.3'),
        TimerAction(period=LaunchConfiguration('p'), actions=[noted('fired')]),
    """)
    yield py("event/timer-cancelled-by-shutdown", """
        TimerAction(period=5.0, actions=[noted('never')]),
        TimerAction(period=0.2, actions=[Shutdown(reason='early')]),
    """)
    yield py("event/process-exit-nonzero", """
        probe('a', additional_env={'PROBE_EXIT': '2'}),
    """)
    yield py("event/required-process", """
        RegisterEventHandler(OnShutdown(on_shutdown=[noted('shutdown',
            LocalSubstitution('event.reason'))])),
        ExecuteProcess(cmd=probe_cmd(), name='req', on_exit=Shutdown(reason='req ended')),
    """)


def opaque_functions() -> Iterator[dict[str, Any]]:
    yield py("opaque/args-kwargs", "OpaqueFunction(function=look, args=['a', 1], "
             "kwargs={'k': 'v'}),", """
        def look(context, first, second, k=None):
            note(first, second, k)
    """)
    yield py("opaque/returns-actions", "OpaqueFunction(function=make),", """
        def make(context):
            return [probe('made'), noted('made', context.launch_configurations.get('x', '-'))]
    """)
    yield py("opaque/returns-none", "OpaqueFunction(function=lambda context: None), probe(),")
    yield py("opaque/returns-include", "OpaqueFunction(function=make),", """
        def make(context):
            return [IncludeLaunchDescription(PythonLaunchDescriptionSource(
                os.path.join(HERE, 'inner.launch.py')), launch_arguments={'who': 'opaque'}.items())]
    """, files={"inner.launch.py": _launch_file("", "DeclareLaunchArgument('who'), "
                                                    "noted('inner', LaunchConfiguration('who')),")})
    yield py("opaque/performs-argument", "DeclareLaunchArgument('n', default_value='2'), "
             "OpaqueFunction(function=make),", """
        def make(context):
            count = int(LaunchConfiguration('n').perform(context))
            return [probe(f'p{i}') for i in range(count)]
    """, args=("n:=3",))
    yield py("opaque/raises", "OpaqueFunction(function=broken), probe(),", """
        def broken(context):
            raise ValueError('opaque broke')
    """)
    yield py("opaque/coroutine", "OpaqueCoroutine(coroutine=later), noted('first'),", """
        import asyncio

        async def later(context):
            await asyncio.sleep(0.2)
            note('coroutine done')
    """)
    yield py("opaque/coroutine-args", "OpaqueCoroutine(coroutine=later, args=['x'], "
             "kwargs={'y': 'z'}),", """
        async def later(context, x, y=None):
            note(x, y)
            return [probe()]
    """)
    yield py("opaque/coroutine-ignore-context", "OpaqueCoroutine(coroutine=later, "
             "ignore_context=True, args=[1]),", """
        async def later(value):
            note('no context', value)
    """)
    yield py("opaque/nested-opaque", "OpaqueFunction(function=outer),", """
        def outer(context):
            return [OpaqueFunction(function=lambda ctx: note('inner', ctx is context))]
    """)


def services() -> Iterator[dict[str, Any]]:
    """A LaunchService run by hand, as scripts and launch's examples run it."""
    yield script("service/run", """
        service = LaunchService()
        service.include_launch_description(LaunchDescription([noted('ran'), probe()]))
        note('returned', service.run())
    """)
    yield script("service/run-argv", """
        service = LaunchService(argv=['x:=given'])
        service.include_launch_description(LaunchDescription([
            DeclareLaunchArgument('x', default_value='default'),
            noted(LaunchConfiguration('x'))]))
        note('returned', service.run())
    """)
    yield script("service/run-twice", """
        service = LaunchService()
        service.include_launch_description(LaunchDescription([noted('ran')]))
        note('first', service.run())
        try:
            note('second', service.run())
        except Exception as error:
            note('second raised', type(error).__name__)
    """)
    yield script("service/run-async", """
        import asyncio

        async def main():
            service = LaunchService()
            service.include_launch_description(LaunchDescription([noted('async ran'), probe()]))
            return await service.run_async()

        note('returned', asyncio.run(main()))
    """)
    yield script("service/shutdown", """
        import asyncio

        async def main():
            service = LaunchService()
            service.include_launch_description(LaunchDescription([
                probe('sleeper', additional_env={'PROBE_SLEEP': '30'})]))
            task = asyncio.ensure_future(service.run_async())
            await asyncio.sleep(1.0)
            service.shutdown()
            return await task

        note('returned', asyncio.run(main()))
    """)
    yield script("service/emit-event", """
        service = LaunchService()
        service.include_launch_description(LaunchDescription([
            RegisterEventHandler(OnShutdown(on_shutdown=[noted('shutdown',
                LocalSubstitution('event.reason'))])),
            ExecuteProcess(cmd=['sleep', '30']),
            RegisterEventHandler(OnProcessStart(on_start=lambda event, context:
                service.emit_event(ShutdownEvent(reason='emitted')))),
        ]))
        note('returned', service.run())
    """)
    yield script("service/context", """
        service = LaunchService(argv=['a:=1'])
        note(type(service.context).__name__, service.context.argv)
    """)
    yield script("service/failing-description", """
        service = LaunchService()
        service.include_launch_description(LaunchDescription([
            OpaqueFunction(function=lambda context: 1 / 0)]))
        note('returned', service.run())
    """)
    yield script("service/include-file", """
        service = LaunchService()
        service.include_launch_description(IncludeLaunchDescription(
            PythonLaunchDescriptionSource(os.path.join(HERE, 'inner.launch.py'))))
        note('returned', service.run())
    """, files={"inner.launch.py": _launch_file("", "noted('inner'), probe(),")})
    yield script("service/include-twice", """
        service = LaunchService()
        service.include_launch_description(LaunchDescription([noted('one')]))
        service.include_launch_description(LaunchDescription([noted('two')]))
        note('returned', service.run())
    """)
    yield script("service/process-exit-code", """
        service = LaunchService()
        service.include_launch_description(LaunchDescription([
            probe(additional_env={'PROBE_EXIT': '4'})]))
        note('returned', service.run())
    """)
    yield script("service/noninteractive", """
        service = LaunchService(noninteractive=True)
        service.include_launch_description(LaunchDescription([
            OpaqueFunction(function=lambda context: note(context.noninteractive))]))
        note('returned', service.run())
    """)


def utilities() -> Iterator[dict[str, Any]]:
    """LaunchIntrospector, launch.logging and launch.utilities."""
    yield script("utility/introspector", """
        description = LaunchDescription([
            LogInfo(msg='hello'),
            DeclareLaunchArgument('a', default_value='1', description='an argument'),
            ExecuteProcess(cmd=['echo', LaunchConfiguration('a')]),
            GroupAction([SetLaunchConfiguration('b', '2')]),
        ])
        for line in LaunchIntrospector().format_launch_description(description).splitlines():
            if 'object at 0x' not in line:  # (where an object was made differs run to run)
                note(line)
    """)
    yield script("utility/introspector-substitutions", """
        for entity in (EnvironmentVariable('HOME'), LaunchConfiguration('x'),
                       FindExecutable(name='ls'), PythonExpression(['1+1']),
                       TextSubstitution(text='t'), ThisLaunchFileDir()):
            note(entity.describe())
    """)
    yield script("utility/normalize", """
        for value in ('text', ['a', LaunchConfiguration('x')], LaunchConfiguration('y')):
            found = normalize_to_list_of_substitutions(value)
            note(*[type(item).__name__ for item in found])
    """)
    yield script("utility/perform", """
        context = LaunchContext()
        context.launch_configurations['x'] = 'ex'
        note(perform_substitutions(context, normalize_to_list_of_substitutions(
            ['a-', LaunchConfiguration('x')])))
    """)
    yield script("utility/perform-needs-substitutions", """
        context = LaunchContext()
        context.launch_configurations['x'] = 'ex'
        note(perform_substitutions(context, ['a-', LaunchConfiguration('x')]))
    """)
    yield script("utility/ensure-argument-type", """
        try:
            launch.utilities.ensure_argument_type(1, str, 'value', 'caller')
        except TypeError as error:
            note('TypeError', error)
        launch.utilities.ensure_argument_type('ok', [str, int], 'value')
        note('accepted')
    """)
    yield script("utility/is-a", """
        note(launch.utilities.is_a(LogInfo(msg='m'), Action),
             launch.utilities.is_a_subclass(LogInfo(msg='m'), Action),
             launch.utilities.is_a('x', int))
    """)
    yield script("utility/type-utils", """
        from launch.utilities.type_utils import get_typed_value, is_valid_scalar_type
        note(get_typed_value('1', int), get_typed_value('1.5', float),
             get_typed_value('true', bool), get_typed_value('[1, 2]', list[int]),
             is_valid_scalar_type(int))
    """)
    yield script("utility/logging-logger", """
        logger = launch.logging.get_logger('corpus')
        note(logger.name, type(logger).__name__, launch.logging.get_logger().name)
    """)
    yield script("utility/logging-output-loggers", """
        out, err = launch.logging.get_output_loggers('proc', 'screen')
        note(out.name, err.name)
    """)
    yield script("utility/substitution-failure", """
        context = LaunchContext()
        try:
            LaunchConfiguration('nothing').perform(context)
        except launch.substitutions.SubstitutionFailure as error:
            note('SubstitutionFailure', 'nothing' in str(error))
    """)
    yield script("utility/launch-description-arguments", """
        description = LaunchDescription([
            DeclareLaunchArgument('a', default_value='1'),
            GroupAction([DeclareLaunchArgument('b')]),
        ])
        note(*[argument.name for argument in description.get_launch_arguments()])
    """)
    yield script("utility/declare-argument-fields", """
        argument = DeclareLaunchArgument('mode', default_value='fast', description='speed',
                                         choices=['fast', 'slow'])
        note(argument.name, argument.description, argument.choices,
             isinstance(argument.default_value[0], TextSubstitution))
    """)
    yield py("utility/declare-argument-choice-refused",
             "DeclareLaunchArgument('mode', default_value='fast', choices=['fast', 'slow']), "
             "probe(),", args=("mode:=medium",))
    yield py("utility/log-info", "LogInfo(msg=['hello ', LaunchConfiguration('x', "
             "default='there')]), probe(),")


def parameters() -> Iterator[dict[str, Any]]:
    """launch_ros's parameters: dicts, files, ParameterFile, ParameterValue."""
    values = {
        "dict": "{'a': 1, 'b': 'two', 'c': 1.5, 'd': True}",
        "dict-list": "{'ints': [1, 2], 'strs': ['a', 'b']}",
        "dict-nested": "{'group': {'x': 1, 'y': {'z': 'deep'}}}",
        "dict-substitution": "{'who': LaunchConfiguration('x')}",
        "dict-substitution-typed": "{'n': LaunchConfiguration('n')}",
        "dict-substitution-key": "{LaunchConfiguration('x'): 1}",
        "value-int": "{'n': ParameterValue(LaunchConfiguration('n'), value_type=int)}",
        "value-str": "{'n': ParameterValue(LaunchConfiguration('n'), value_type=str)}",
        "value-list": "{'l': ParameterValue([1, 2], value_type=list[int])}",
        "value-list-text-refused": "{'l': ParameterValue('[1, 2]', value_type=list[int])}",
        "value-yaml": "{'y': ParameterValue('{a: 1}')}",
        "value-command": "{'robot_description': ParameterValue(Command(['echo ', "
                         "LaunchConfiguration('x')]), value_type=str)}",
        "file-path": "os.path.join(HERE, 'p.yaml')",
        "file-substitution": "PathJoinSubstitution([ThisLaunchFileDir(), 'p.yaml'])",
        "parameter-file": "ParameterFile(os.path.join(HERE, 'p.yaml'))",
        "parameter-file-substs": "ParameterFile(os.path.join(HERE, 'subst.yaml'), "
                                 "allow_substs=True)",
        "parameter-file-no-substs": "ParameterFile(os.path.join(HERE, 'subst.yaml'))",
        "two-dicts": "{'a': 1}, {'a': 2, 'b': 3}",
        "dict-then-file": "{'f': 0}, os.path.join(HERE, 'p.yaml')",
    }
    files = {"p.yaml": "/**:\n  ros__parameters:\n    f: 1\n    g: [a, b]\n",
             "subst.yaml": "/**:\n  ros__parameters:\n    who: $(var x)\n"}
    for label, value in values.items():
        yield py(f"parameter/{label}", "SetLaunchConfiguration('x', 'value'), "
                 f"SetLaunchConfiguration('n', '7'), probe(parameters=[{value}]),", files=files)
    yield py("parameter/set-parameter", "SetParameter(name='s', value=1), probe(),")
    yield py("parameter/set-parameter-in-group",
             "GroupAction([SetParameter(name='s', value='g'), probe('a')]), probe('b'),")
    yield py("parameter/set-parameters-from-file",
             "SetParametersFromFile(os.path.join(HERE, 'p.yaml')), probe(),",
             files={"p.yaml": "/**:\n  ros__parameters:\n    f: 1\n"})
    yield py("parameter/set-use-sim-time", "SetUseSimTime(True), probe(),")
    yield py("parameter/substitution-parameter",
             "SetParameter(name='s', value='read'), "
             "noted(launch_ros.substitutions.Parameter('s')),",
             "import launch_ros.substitutions")


def ros_actions() -> Iterator[dict[str, Any]]:
    """launch_ros's actions and Node's arguments."""
    yield py("ros/push-ros-namespace", "GroupAction([PushROSNamespace('g'), probe()]),")
    yield py("ros/push-ros-namespace-nested",
             "GroupAction([PushROSNamespace('a'), GroupAction([PushROSNamespace('b'), "
             "probe()])]),")
    yield py("ros/push-ros-namespace-absolute",
             "GroupAction([PushROSNamespace('a'), probe(namespace='/abs')]),")
    yield py("ros/push-ros-namespace-substitution",
             "SetLaunchConfiguration('ns', 'robot1'), "
             "GroupAction([PushROSNamespace(LaunchConfiguration('ns')), probe()]),")
    yield py("ros/push-ros-namespace-old-name",
             "GroupAction([launch_ros.actions.PushRosNamespace('g'), probe()]),",
             "import launch_ros.actions")
    yield py("ros/set-remap", "GroupAction([SetRemap(src='a', dst='b'), probe()]),")
    yield py("ros/set-ros-log-dir", "RegisterEventHandler(OnProcessStart(on_start=lambda event, "
             "context: note(event.env.get('ROS_LOG_DIR')))), "
             "SetROSLogDir(os.path.join(HERE, 'logs')), probe(),")
    yield py("ros/ros-timer", "RosTimer(period=0.3, actions=[noted('ros timer'), probe()]),")
    yield py("ros/node-arguments", "probe(arguments=['a', 'b c'], ros_arguments=["
             "'--log-level', 'warn'], namespace='ns', exec_name='label'),")
    yield py("ros/node-remappings", "probe(remappings=[('a', 'b'), ('~/c', 'd')]),")
    yield py("ros/node-env", "probe(additional_env={'PROBE_E': '1'}),")
    yield py("ros/node-no-name", "Node(package='probe', executable='probe'),")
    yield py("ros/node-respawn", "probe(respawn=True, respawn_delay=0.5),", stop_after=3.0)
    yield py("ros/node-name-field", "node, OpaqueFunction(function=lambda context: note("
             "node.node_name, node.expanded_node_namespace)),",
             "node = probe('named', namespace='ns')")
    yield py("ros/executable-in-package-process",
             "ExecuteProcess(cmd=probe_cmd('--flag'), name='e'),")
    yield py("ros/execute-local", """
        ExecuteLocal(process_description=launch.descriptions.Executable(cmd=probe_cmd('local'),
                                                                        name='loc')),
    """, "import launch.descriptions")
    yield py("ros/execute-process-shell", "ExecuteProcess(cmd=[probe_cmd()[0], ' shell-arg'], "
             "shell=True),")
    yield py("ros/execute-process-env", "ExecuteProcess(cmd=probe_cmd(), env={'PROBE_ONLY': "
             "'1', 'PATH': '/usr/bin:/bin', 'PROBE_OUT': os.environ['PROBE_OUT']}),")
    yield py("ros/include-with-arguments", """
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            [ThisLaunchFileDir(), '/inner.launch.py']),
            launch_arguments=[('who', 'included')]),
        noted('outer sees', LaunchConfiguration('who', default='unset')),
    """, files={"inner.launch.py": _launch_file(
        "", "DeclareLaunchArgument('who', default_value='d'), probe(LaunchConfiguration('who')),")})
    yield py("ros/include-scoped-namespace", """
        GroupAction([PushROSNamespace('g'), IncludeLaunchDescription(
            PythonLaunchDescriptionSource([ThisLaunchFileDir(), '/inner.launch.py']))]),
        probe('outside'),
    """, files={"inner.launch.py": _launch_file("", "probe('inside'),")})
    yield py("ros/include-xml", """
        IncludeLaunchDescription(launch.launch_description_sources.AnyLaunchDescriptionSource(
            [ThisLaunchFileDir(), '/inner.launch.xml']), launch_arguments={'v': '5'}.items()),
    """, "import launch.launch_description_sources",
             files={"inner.launch.xml": '<launch><arg name="v"/><node pkg="probe" exec="probe" '
                                        'name="x"><param name="v" value="$(var v)"/></node>'
                                        '</launch>\n'})


def lifecycle() -> Iterator[dict[str, Any]]:
    """A lifecycle node driven by launch_ros's events, as launch files drive one. (Each ends
    its launch itself; `stop_after` keeps a run from being taken as settled while the real
    tool's lifecycle services are still being discovered.)"""
    for spec in _lifecycle():
        yield {"stop_after": 15.0, **spec}


def _lifecycle() -> Iterator[dict[str, Any]]:
    node = "LifecycleNode(package='probe', executable='lifecycle_probe', name='life', namespace='')"
    yield py("lifecycle/configure-then-activate", """
        RegisterEventHandler(OnStateTransition(target_lifecycle_node=life, goal_state='inactive',
            entities=[noted('inactive'), EmitEvent(event=ChangeState(
                lifecycle_node_matcher=matches_node_name('/life'),
                transition_id=lifecycle_msgs.msg.Transition.TRANSITION_ACTIVATE))])),
        RegisterEventHandler(OnStateTransition(target_lifecycle_node=life, goal_state='active',
            entities=[noted('active'), Shutdown(reason='active')])),
        life,
        EmitEvent(event=ChangeState(lifecycle_node_matcher=launch.events.matches_action(life),
            transition_id=lifecycle_msgs.msg.Transition.TRANSITION_CONFIGURE)),
    """, f"life = {node}")
    yield py("lifecycle/transition-fields", """
        RegisterEventHandler(OnStateTransition(target_lifecycle_node=life, goal_state='inactive',
                                               entities=[OpaqueFunction(function=seen)])),
        life,
        EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_node_name('/life'),
            transition_id=lifecycle_msgs.msg.Transition.TRANSITION_CONFIGURE)),
    """, f"""
        life = {node}

        def seen(context):
            event = context.locals.event
            note(type(event).__name__, repr(event.transition), event.start_state,
                 event.goal_state, event.action is life)
            return [Shutdown(reason='seen')]
    """)
    yield py("lifecycle/matches-node-name", """
        RegisterEventHandler(OnProcessStart(target_action=life, on_start=lambda event, context:
            [noted(str(matches_node_name('/life')(life)), str(matches_node_name('/other')(life))),
             TimerAction(period=1.5, actions=[Shutdown(reason='matched')])])),
        life,
    """, f"life = {node}")
    yield py("lifecycle/matches-node-name-before-start", """
        OpaqueFunction(function=lambda context: note(
            matches_node_name('/life')(life), matches_node_name('/other')(life))),
    """, f"life = {node}")
    yield py("lifecycle/starts-unconfigured", """
        life,
        TimerAction(period=1.0, actions=[Shutdown(reason='done')]),
    """, f"life = {node}")


def specs() -> Iterator[dict[str, Any]]:
    yield from actions()
    yield from context_api()
    yield from substitutions()
    yield from conditions()
    yield from events()
    yield from opaque_functions()
    yield from services()
    yield from utilities()
    yield from parameters()
    yield from ros_actions()
    yield from lifecycle()
