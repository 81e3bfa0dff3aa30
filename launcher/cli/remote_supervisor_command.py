"""`launcher remote-supervisor`: what a launch runs on another host over ssh (runtime/
supervisor.py), given this host's packages, environment and bus."""

from __future__ import annotations

import argparse
import os
import socket
from pathlib import Path
from typing import Any

from launcher.bus import places
from launcher.cli import remote_bridge
from launcher.cli.launch_command import children_environment
from launcher.cli.workspace import load_index
from launcher.errors import LaunchError, did_you_mean
from launcher.packages.executables import find_executable
from launcher.packages.index import PackageIndex
from launcher.runtime.custody import Custody
from launcher.runtime.loop import EventLoop
from launcher.runtime.remote_files import LaunchFolder, sweep_stale
from launcher.runtime.supervisor import Host, Resolve, Supervisor
from launcher.runtime.system import System


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.description = (
        "(internal) What a launch runs on another host over ssh: it starts the launch's "
        "processes on this host and speaks launcher's remote protocol on its stdin and stdout "
        "(not for a terminal). It ends them all when the launch ends, goes silent or is cut "
        "off.")


def run(args: argparse.Namespace) -> int:
    frames_in, frames_out = _own_channel()
    custody = Custody()
    custody.begin()  # first: whatever the hooks start is the launch's too
    index = load_index()
    host_name = socket.gethostname()
    run_folder = Path(places.run_folder(os.environ))
    sweep_stale(run_folder)
    host = Host(name=host_name, environment=children_environment(index, debug=False),
                run_folder=run_folder, resolve=resolver(index, host_name),
                join_graph=join_graph)
    return Supervisor(EventLoop(), System(), custody, host, frames_in, frames_out).run()


def _own_channel() -> tuple[int, int]:
    """The channel's fds, private: fd 1 then points at stderr and fd 0 at /dev/null, so that
    a stray print, or a hook reading its stdin, cannot touch the frames."""
    frames_in, frames_out = os.dup(0), os.dup(1)
    os.dup2(2, 1)
    null = os.open(os.devnull, os.O_RDONLY)
    os.dup2(null, 0)
    os.close(null)
    return frames_in, frames_out


def resolver(index: PackageIndex, host: str) -> Resolve:
    """Finds a node's executable in this host's packages, as `node` does on the launching
    host; the error says which host looked, and where."""

    def resolve(package: str, executable: str, env: dict[str, str]) -> tuple[
            list[str], dict[str, str]]:
        if package not in index:
            searched = ", ".join(f"{root.path} ({root.origin})" for root in index.roots)
            raise LaunchError(f"package '{package}' not found on {host}"
                              f"{did_you_mean(package, index.packages)}; searched: {searched}"
                              f" (its env-loader, or its login, sets LAUNCHER_PACKAGE_PATH or "
                              f"AMENT_PREFIX_PATH there)")
        try:
            found = find_executable(index.get(package), executable)
        except LaunchError as exc:
            raise LaunchError(f"on {host}: {exc.message}") from None
        return list(found.argv), found.environment(env)

    return resolve


def join_graph(folder: LaunchFolder, graph: dict[str, Any]) -> dict[str, str]:
    """This host's graph joins the launch's: a bridge from this host's router to the router
    the launch names, with the launch's credentials (written in its folder, 0600), once it has
    joined. A process here then joins this host's router as any does: nothing to add to its
    environment. A LaunchError says why this host cannot join."""
    env = dict(os.environ)  # (the supervisor's mark with it: its clean-up ends the bridge)
    if graph.get("domain") is not None:
        env[places.DOMAIN_VARIABLE] = str(graph["domain"])
    remote_bridge.start(graph["router"], folder.credentials(graph["credentials"]), env,
                        socket.gethostname(), folder.path / "bridge.log")
    return {}
