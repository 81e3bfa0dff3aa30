"""Where launcher differs from the real tool on purpose: each case, what launcher does
instead, and why. The docs page of deliberate differences is made from this table
(docs/_gen), so the list a user reads is the list the test holds launcher to.
"""

from __future__ import annotations

import copy
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any


@dataclass(frozen=True)
class Choice:
    reason: str  # one or two sentences, for the docs
    change: Callable[[dict[str, Any]], None]  # turns the recorded outcome into launcher's

    def apply(self, recorded: dict[str, Any]) -> dict[str, Any]:
        chosen = copy.deepcopy(recorded)
        self.change(chosen)
        return chosen


def exits(code: Any) -> Callable[[dict[str, Any]], None]:
    def change(outcome: dict[str, Any]) -> None:
        outcome["exit"] = code
    return change


def starts_nothing(code: int = 1) -> Callable[[dict[str, Any]], None]:
    def change(outcome: dict[str, Any]) -> None:
        outcome.update(exit=code, starts=[], restarted=[])
    return change


# Reasons shared by several cases
CRASH_REPORTED = ("ROS 2's launch crashes on this input with a Python traceback (its own "
                  "bug); launcher reports a located error and starts nothing.")

NOT_STARTED_FAILS = ("roslaunch logs that it cannot launch the node, runs on with nothing "
                     "of it, and exits 0 when stopped; launcher reports the missing package "
                     "or executable at its place in the file, and the launch's exit status "
                     "is 1, so a script or a test sees it.")

NODE_FAILED = ("roslaunch and ROS 2's launch log that a process died and exit 0; launcher's "
               "exit status is 1 when a process exits with an error that the launch did not "
               "cause, so a script or a test sees the failure.")

PROCESS_LABEL = ("launcher labels a node's process by its node name (`a-1`), launch_ros by "
                 "its executable's (`probe-1`): with several nodes of one executable, the "
                 "label tells them apart. A Node's `name` is that label in both, once it "
                 "has run.")


LOGGERS = ("launch.logging's loggers are children of launcher's `launch` logger "
           "(`launch.NAME`), so that what they print is formatted as the launch's output and "
           "other libraries' logging in the same process is not printed; launch's are named "
           "as given, under the root logger.")

SIM_TIME = ("launch_ros 0.28's SetUseSimTime sets use_sim_time only on the launch's own ROS "
            "node (what its RosTimers count), which no node sees; launcher gives it to the "
            "nodes started after it, as the action's name says and as users write it for.")


def becomes(outcome: dict[str, Any]) -> Callable[[dict[str, Any]], None]:
    """The outcome launcher has instead (where the real tool fails and launcher does not)."""
    def change(recorded: dict[str, Any]) -> None:
        recorded.clear()
        recorded.update(copy.deepcopy(outcome))
    return change


def noting(*notes: list[str], code: Any = None) -> Callable[[dict[str, Any]], None]:
    """What launcher's Python case notes instead (and its exit status, when it differs)."""
    def change(outcome: dict[str, Any]) -> None:
        outcome["notes"] = [list(note) for note in notes]
        if code is not None:
            outcome["exit"] = code
    return change


def refused(outcome: dict[str, Any]) -> None:
    """The launch fails, at the user's line, before its case notes anything."""
    outcome.update(exit=1, starts=[], restarted=[])
    outcome.pop("notes", None)


def _probe(argv: list[str]) -> dict[str, Any]:
    return {"argv": argv, "cwd": "<case>", "env": {}, "name": "n"}


CHOICES: dict[str, Choice] = {
    "ros1/subst/unclosed": Choice(
        "roslaunch keeps an unclosed `$(arg a` as text and passes the typo on to the node; "
        "launcher refuses it at its place in the file, and starts nothing.",
        starts_nothing()),
    "ros1/group/ns-bad-name": Choice(
        "roslaunch passes a namespace holding a space on to its nodes, where ROS names "
        "cannot hold one; launcher refuses the invalid name at its place, and starts "
        "nothing.", starts_nothing()),
    "ros1/node/type-missing": Choice(NOT_STARTED_FAILS, exits(1)),
    "ros1/node/package-missing": Choice(NOT_STARTED_FAILS, exits(1)),
    "ros1/node/exits-nonzero": Choice(NODE_FAILED, exits(1)),
    "ros2/xml/param/from-missing-file": Choice(
        "launch_ros hands a parameters file that does not exist to the node, which fails when "
        "rcl cannot open it; launcher reports the missing file at its place in the launch "
        "file, and starts nothing.", starts_nothing()),
    "ros2/xml/node/no-pkg": Choice(
        "A node without pkg runs its executable from PATH in both; when it is not there, "
        "ROS 2's launch prints a Python traceback and runs on with nothing started, "
        "launcher says it cannot start the command, at the node's place, and exits 1.",
        exits(1)),
    "ros2/xml/param/set-use-sim-time": Choice(
        "launch_ros 0.28 exposes `<set_use_sim_time>` to XML and YAML, but its parser fails "
        "on every value (\"Type '1' and value … do not agree\", its own bug). " + SIM_TIME,
        becomes({"exit": "ok", "restarted": [], "starts": [_probe(
            ["--ros-args", "-r", "__node:=n", "-p", "use_sim_time:=true"])]})),
    "ros2/python/substitution/python-expression-modules": Choice(
        "launcher evaluates PythonExpression with its own restricted evaluator (math, a few "
        "builtins and string methods), never Python's eval: its text is made of launch "
        "arguments, which come from the command line. Other modules (python_modules=['os']) "
        "are refused at the expression's line.", refused),
    "ros2/python/event/on-process-exit-returncode": Choice(
        "LocalSubstitution('event.returncode') is a number; launch fails joining it into "
        "text, launcher gives its text.", noting(["exit", "3"])),
    "ros2/python/event/on-process-exit-any": Choice(
        PROCESS_LABEL, noting(["exit", "a-1", "0"])),
    "ros2/python/event/handler-once": Choice(PROCESS_LABEL, noting(["once", "a-1"])),
    "ros2/python/event/on-process-io": Choice(
        "launcher hands OnProcessIO one event per line of output; launch hands it what one "
        "read of the pipe returned (here both lines; often part of one).",
        noting(["ProcessStdout", "['one']"], ["ProcessStdout", "['two']"])),
    "ros2/python/event/on-include-handler": Choice(
        "launch's OnIncludeLaunchDescription fails on its own entities (\"'OpaqueFunction' "
        "object is not iterable\"); launcher's includes the event's description, as the "
        "launch's own handler also does.", noting(["included"], ["included"], code="ok")),
    "ros2/python/event/process-exit-nonzero": Choice(NODE_FAILED, exits(1)),
    "ros2/python/service/process-exit-code": Choice(
        NODE_FAILED + " LaunchService.run() returns that status.", noting(["returned", "1"])),
    "ros2/python/service/run-twice": Choice(
        "A second LaunchService.run() does nothing in launch and returns 0; launcher says at "
        "the caller's line that a launch service runs once, and returns 1.",
        noting(["ran"], ["first", "0"], ["second", "1"])),
    "ros2/python/service/emit-event": Choice(
        "LaunchService.emit_event() called on the launch's own thread (from a handler) "
        "waits in launch until something else wakes its loop (here Ctrl-C); launcher "
        "handles the event at once.", noting(["shutdown", "emitted"], ["returned", "0"])),
    "ros2/python/utility/perform-needs-substitutions": Choice(
        "launch.utilities.perform_substitutions takes only substitutions and fails on plain "
        "text in the list; launcher takes text too.", noting(["a-ex"], code="ok")),
    "ros2/python/utility/logging-logger": Choice(
        LOGGERS, noting(["launch.corpus", "Logger", "launch"])),
    "ros2/python/utility/logging-output-loggers": Choice(
        LOGGERS, noting(["launch.proc", "launch.proc"])),
    "ros2/python/parameter/dict-list": Choice(
        "launch_ros writes a list given in a Python dict to the node's parameters file as "
        "`!!python/tuple` (rcl reads it as a list); launcher writes a plain YAML list.",
        lambda outcome: outcome["starts"][0].update(parameter_files=[
            {"/**": {"ros__parameters": {"ints": [1, 2], "strs": ["a", "b"]}}}])),
    "ros2/python/parameter/value-list-text-refused": Choice(
        "ParameterValue('[1, 2]', value_type=list[int]) fails in launch_ros (the text is "
        "not a list); launcher reads the text as YAML, as it reads the same value from XML.",
        becomes({"exit": "ok", "restarted": [], "starts": [{
            **_probe(["--ros-args", "-r", "__node:=n", "--params-file", "<params:0>"]),
            "parameter_files": [{"/**": {"ros__parameters": {"l": [1, 2]}}}]}]})),
    "ros2/python/parameter/set-use-sim-time": Choice(
        SIM_TIME, lambda outcome: outcome["starts"][0]["argv"].extend(
            ["-p", "use_sim_time:=true"])),
    "ros2/yaml/node/respawn-bool": Choice(
        "launch's YAML frontend refuses `respawn: true` (a YAML boolean) and takes only the "
        "text 'true'; launcher takes both, as YAML users write booleans.",
        becomes({"exit": "ok", "restarted": ["n"], "starts": [_probe(
            ["--ros-args", "-r", "__node:=n"])]})),
}
