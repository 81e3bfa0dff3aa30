"""launch_testing.util: KeepAliveProc, and finding a test's processes by action or by name."""

from __future__ import annotations

from typing import Any

from launcher.api import ExecuteProcess

NO_CMD_ARGS = object()  # cmd_args that matches a process started with no arguments
# a process that waits for the launch to stop it, and ends cleanly (0) when it does: a shell,
# whose trap is set within a millisecond of its start (an interpreter's handler comes tens of
# milliseconds later, and a test that ends sooner would see it die of the signal)
_KEEP_ALIVE = "trap 'exit 0' INT TERM; while :; do sleep 1; done"


class NoMatchingProcessException(Exception):
    pass


def KeepAliveProc() -> Any:  # noqa: N802 - launch_testing's name
    """A process that does nothing until the launch ends: it keeps a launch whose processes
    under test end by themselves running while the active tests run."""
    return ExecuteProcess(cmd=["/bin/sh", "-c", _KEEP_ALIVE])


def _details(process: Any) -> dict[str, Any]:
    return getattr(process, "process_details", None) or {}


def _describe(process: Any) -> str:
    details = _details(process)
    if details:
        return " ".join([details["name"], *details["cmd"][1:]])
    return "Unknown - Process not launched yet"


def _matches_args(process: Any, cmd_args: Any) -> bool:
    cmd = _details(process).get("cmd", [])
    if cmd_args is None:
        return True
    if cmd_args is NO_CMD_ARGS:
        return len(cmd) == 1
    return cmd_args in " ".join(cmd[1:])


def resolveProcesses(info_obj: Any, *, process: Any = None, cmd_args: Any = None,  # noqa: N802
                     strict_proc_matching: bool = True) -> list[Any]:
    """The launch actions of `info_obj`'s processes that `process` names: an action itself,
    a name (part of the process's name, `cmd_args` part of its arguments), or every one."""
    known = list(info_obj.processes())
    if process is None or process == "":
        if not known:
            raise NoMatchingProcessException("No data recorded for any process")
        return known
    if not isinstance(process, str):
        if process not in known:
            raise NoMatchingProcessException(f"No data recorded for proc {_describe(process)}")
        return [process]
    matches = [p for p in known if process in _details(p).get("name", "") and
               _matches_args(p, cmd_args)]
    if not matches:
        names = ", ".join(sorted(_describe(p) for p in known))
        raise NoMatchingProcessException(
            f"Did not find any processes matching name '{process}' and args '{cmd_args}'. "
            f"Procs: {names}")
    if strict_proc_matching and len(matches) > 1:
        names = ", ".join(sorted(_describe(p) for p in matches))
        raise Exception(f"Found multiple processes matching name '{process}' and cmd_args "
                        f"'{cmd_args}'. Procs: {names}")
    return matches
