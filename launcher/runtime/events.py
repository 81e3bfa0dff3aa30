"""Events the runtime emits, shaped as launch's (launch.events…): a handler of the user's
own reads the same fields it reads under ros2 launch (`event.returncode`, `event.action`,
`event.text` as bytes, …); `line` is an output event's text as the line launcher read."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from operator import attrgetter
from typing import Any, Protocol


class Event:
    """launch.Event: the base of every event; `name` is its type's dotted name."""

    name = "launch.event.Event"


class RunningProcessEvent(Event):
    """launch.events.process.RunningProcessEvent: something about a process of an action."""

    name = "launch.events.process.RunningProcessEvent"

    def __init__(self, *, action: Any, name: str, cmd: Sequence[str], cwd: str | None,
                 env: Mapping[str, str] | None, pid: int | None) -> None:
        self.action, self.process_name = action, name
        self.cmd, self.cwd, self.env, self.pid = cmd, cwd, env, pid

    execute_process_action = property(attrgetter("action"))  # (launch has both names)

    def __repr__(self) -> str:
        return f"{type(self).__name__}(name={self.process_name!r}, pid={self.pid})"


class ProcessStarted(RunningProcessEvent):
    name = "launch.events.process.ProcessStarted"

    def __init__(self, **kwargs: Any) -> None:
        super().__init__(**kwargs)


class ProcessExited(RunningProcessEvent):
    name = "launch.events.process.ProcessExited"

    def __init__(self, *, returncode: int | None, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.returncode = returncode


class ProcessIO(RunningProcessEvent):
    """Output of a process: `text` as bytes, `fd` 1 (stdout) or 2 (stderr)."""

    name = "launch.events.process.ProcessIO"

    def __init__(self, *, text: bytes, fd: int, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.text, self.fd = text, fd

    @property
    def from_stdout(self) -> bool:
        return self.fd == 1

    @property
    def from_stderr(self) -> bool:
        return self.fd == 2

    @property
    def from_stdin(self) -> bool:
        return self.fd == 0

    @property
    def stream(self) -> str:
        return {0: "stdin", 1: "stdout"}.get(self.fd, "stderr")

    @property
    def line(self) -> str:
        return self.text.decode(errors="replace").removesuffix("\n")


class ProcessStdout(ProcessIO):
    name = "launch.events.process.ProcessStdout"

    def __init__(self, *, text: bytes, **kwargs: Any) -> None:
        super().__init__(text=text, fd=1, **kwargs)


class ProcessStderr(ProcessIO):
    name = "launch.events.process.ProcessStderr"

    def __init__(self, *, text: bytes, **kwargs: Any) -> None:
        super().__init__(text=text, fd=2, **kwargs)


class ProcessStdin(ProcessIO):
    name = "launch.events.process.ProcessStdin"

    def __init__(self, *, text: bytes, **kwargs: Any) -> None:
        super().__init__(text=text, fd=0, **kwargs)


class Shutdown(Event):
    """launch.events.Shutdown: the launch is ending (`due_to_sigint`: Ctrl-C ended it)."""

    name = "launch.events.Shutdown"

    def __init__(self, *, reason: str = "reason not given", due_to_sigint: bool = False) -> None:
        self.reason, self.due_to_sigint = reason, due_to_sigint

    def __repr__(self) -> str:
        return f"Shutdown(reason={self.reason!r})"


class ExecutionComplete(Event):
    """launch.events.ExecutionComplete: an action is done (a process action: its process
    ended)."""

    name = "launch.events.ExecutionComplete"

    def __init__(self, *, action: Any) -> None:
        self.action = action


class TimerEvent(Event):
    """launch.events.TimerEvent: a TimerAction's period is over."""

    name = "launch.events.TimerEvent"

    def __init__(self, *, timer_action: Any) -> None:
        self.timer_action = timer_action


class IncludeLaunchDescription(Event):
    """launch.events.IncludeLaunchDescription: include this description now (what a handler
    emits to add actions to a running launch)."""

    name = "launch.events.IncludeLaunchDescription"

    def __init__(self, launch_description: Any) -> None:
        self.launch_description = launch_description


class ProcessTargetedEvent(Event):
    """launch.events.process.ProcessTargetedEvent: for the process actions that
    `process_matcher(action)` picks."""

    name = "launch.events.process.ProcessTargetedEvent"

    def __init__(self, *, process_matcher: Any) -> None:
        self.process_matcher = process_matcher


class ShutdownProcess(ProcessTargetedEvent):
    """Stop the matching processes, with their own signal sequence."""

    name = "launch.events.process.ShutdownProcess"


class SignalProcess(ProcessTargetedEvent):
    """Send `signal_number` (a number, or a name such as 'SIGINT') to the matching
    processes."""

    name = "launch.events.process.SignalProcess"

    def __init__(self, *, signal_number: Any, process_matcher: Any) -> None:
        super().__init__(process_matcher=process_matcher)
        self.signal_number = signal_number

    @property
    def signal(self) -> int:
        import signal

        number = self.signal_number
        return int(getattr(signal, number)) if isinstance(number, str) else int(number)

    @property
    def signal_name(self) -> str:
        import signal

        return signal.Signals(self.signal).name


def output(action: Any, name: str, stream: str, line: str, cmd: Sequence[str] = (),
           pid: int | None = None) -> ProcessIO:
    """The event of one line a process printed on `stream` (stdout or stderr)."""
    kind = ProcessStdout if stream == "stdout" else ProcessStderr
    return kind(text=(line + "\n").encode(), action=action, name=name, cmd=cmd, cwd=None,
                env=None, pid=pid)


class EventHandler(Protocol):
    def matches(self, event: Event) -> bool: ...

    def handle(self, event: Event, context: Any) -> Sequence[Any] | None: ...
