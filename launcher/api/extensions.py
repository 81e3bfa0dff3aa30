"""launcher's own Python actions, beyond launch's and launch_ros's (which no ROS has: a file
that imports them says so): `Machine` declares a host processes may run on, over ssh;
`PushMachine` sends the processes after it in its scope there, as PushROSNamespace scopes a
namespace (in a GroupAction, that group's).

    Machine(name="robot2", address="10.0.0.2", user="pi", env_loader="/home/pi/env.sh"),
    GroupAction([PushMachine("robot2"), Node(package="demo", executable="talker")]),
"""

from __future__ import annotations

from typing import Any

from launcher.description.actions import machine as _machine
from launcher.runtime.machine import DEFAULT_TIMEOUT


def Machine(*, name: Any, address: Any, user: Any = None, ssh_port: Any = None,  # noqa: N802
            env_loader: Any = None, timeout: Any = DEFAULT_TIMEOUT, **kw: Any) -> Any:
    """A host the launch may run processes on: its name (what PushMachine names), its
    address as ssh takes it, the user and port to log in with (default: ssh's), a script
    there that sets the environment up and runs its arguments, and the seconds the
    connection may take. One whose address is this host runs its processes here."""
    return _machine.DeclareMachine(name=name, address=address, user=user, ssh_port=ssh_port,
                                   env_loader=env_loader, timeout=timeout, **kw)


def PushMachine(machine: Any, **kw: Any) -> Any:  # noqa: N802
    """The processes after it in its scope run on `machine` (a declared machine's name)."""
    return _machine.PushMachine(name=machine, **kw)


__all__ = ["Machine", "PushMachine"]
