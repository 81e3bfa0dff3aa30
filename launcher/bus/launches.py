"""The running launches on the user's graph, as `launcher ps`, `stop`, `start`, `restart`,
`logs` and the viewer's processes page see them: each launch's node (cli/launch_control.py
serves it) found by its services, and asked.
A process is named by its label (`talker-1`), or by any name it goes by (its node's, its
executable's) when that names one process of all the launches; `--launch` picks one launch by
its file's name, its pid or its node's."""

from __future__ import annotations

import os
from typing import Any, NamedTuple

from launcher.bus import discovery
from launcher.errors import LaunchError, did_you_mean

LIST = "launcher_interfaces/srv/ListProcesses"
CONTROL = "launcher_interfaces/srv/ControlProcess"
OUTPUT = "launcher_interfaces/srv/ProcessOutput"

ASK_WAIT = 6.0  # seconds an answer may take (the launch's own wait is 5)


class Launch(NamedTuple):
    node: str  # its node's full name (/launcher_1234)
    listing: Any  # its ListProcesses response


class Launches:
    def __init__(self, name: str = "_launcher_cli") -> None:
        from launcher.bus.node import Node
        from launcher.bus.session import open_session

        self.node = Node(f"{name}_{os.getpid()}", argv=[], session=open_session("client"),
                         parameter_services=False)

    def close(self) -> None:
        self.node.destroy_node()
        self.node.session.close()

    # --- what runs --------------------------------------------------------------------------
    def all(self) -> list[Launch]:
        """Every running launch that answers, ordered by pid."""
        from launcher.bus import graph  # (Zenoh: the launch imports this module's names)

        found = []
        for entity in graph.servers(self.node.session, "", LIST):
            answer = self._ask(LIST, entity.topic, "")
            if answer is not None:
                found.append(Launch(entity.topic.rsplit("/", 1)[0], answer))
        return sorted(found, key=lambda launch: launch.listing.pid)

    def _ask(self, type_name: str, service: str, what: str, **fields: Any) -> Any:
        client = self.node.create_client(type_name, service)
        try:
            request = self.node.message(f"{type_name}_Request", **fields)
            return client.call(request, ASK_WAIT)
        except LaunchError:
            if what:
                raise
            return None  # (a launch ending as it was asked: not listed)
        finally:
            client.destroy()

    def running(self, launch: str | None = None) -> list[Launch]:
        """The running launches (the one `launch` picks); none is said as an error."""
        launches = self.all()
        if not launches:
            raise LaunchError(f"no launch is running on this graph ({where()}); start one with "
                             "`launcher launch FILE`")
        if launch is None:
            return launches
        picked = [each for each in launches if launch in (
            each.listing.launch, each.listing.launch.split(".", 1)[0],
            str(each.listing.pid), each.node.lstrip("/"), each.node, each.listing.file)]
        if not picked:
            shown = [name for each in launches
                     for name in (each.listing.launch, each.listing.launch.split(".", 1)[0])]
            raise LaunchError(f"--launch {launch}: no running launch is {launch!r}"
                             f"{did_you_mean(launch, shown)}; running: "
                             f"{', '.join(describe(each) for each in launches)}")
        return picked

    def pick(self, name: str, launch: str | None = None) -> tuple[Launch, Any]:
        """The one process `name` names, and its launch."""
        launches = self.running(launch)
        matches = [(each, row) for each in launches for row in each.listing.processes
                   if name == row.name]
        if not matches:
            matches = [(each, row) for each in launches for row in each.listing.processes
                       if name in row.names or name == row.node]
        if len(matches) == 1:
            return matches[0]
        if matches:
            shown = ", ".join(f"{row.name} (in {describe(each)})" for each, row in matches)
            raise LaunchError(f"'{name}' names several processes: {shown}; name one by its "
                             "label" + ("" if launch or len(launches) == 1 else
                                        ", or pick the launch with --launch"))
        every = {n for each in launches for row in each.listing.processes
                 for n in (*row.names, row.node) if n}
        scope = describe(launches[0]) if len(launches) == 1 else \
            f"any of the {len(launches)} running launches"
        unlisted = "".join(f"; {describe(each)} listed none: {each.listing.message}"
                           for each in launches if each.listing.message)
        raise LaunchError(f"no process '{name}' in {scope}{did_you_mean(name, every)} "
                         f"(`launcher ps` lists them){unlisted}")

    # --- asking one launch ------------------------------------------------------------------
    def act(self, launch: Launch, label: str, verb: str) -> str:
        answer = self._ask(CONTROL, f"{launch.node}/control_process", verb, name=label,
                           verb=verb, uid=os.getuid())
        if not answer.success:
            raise LaunchError(f"{verb} {label}: {answer.message}")
        return answer.message

    def output(self, launch: Launch, label: str, after: int) -> Any:
        answer = self._ask(OUTPUT, f"{launch.node}/process_output", "logs", name=label,
                           after=after)
        if not answer.success:
            raise LaunchError(f"logs {label}: {answer.message}")
        return answer


def describe(launch: Launch) -> str:
    return f"{launch.listing.launch or launch.node} (pid {launch.listing.pid})"


def where() -> str:
    """The graph's words: its domain and run folder."""
    domain = os.environ.get("ROS_DOMAIN_ID", "0") or "0"
    return f"ROS_DOMAIN_ID={domain}, {discovery.socket_path(os.environ).parent}"
