"""Tab completion for bash and zsh through argcomplete, as ros2cli has it: commands, verbs
and options, and the names on the running graph (topics, nodes, services) and in the
package index where a command takes one.

`hooks/setup.sh` registers it (`register-python-argcomplete launcher`); the shell then runs
`launcher` with `_ARGCOMPLETE` set, and `complete()` answers. Only the parser of the command
being typed is built, as for a normal run.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from typing import Any


def complete(build_parser: Callable[[list[str]], Any]) -> int:
    """Answer the shell's completion request (argcomplete exits the process); the parser is
    built for the words finished so far, so that only the verb being typed is imported."""
    import argcomplete

    line = os.environ.get("COMP_LINE", "")
    line = line[:int(os.environ.get("COMP_POINT", len(line)))]
    words = line.split()[1:]
    finished = words if line.endswith(" ") else words[:-1]
    parser, _ = build_parser(finished)
    argcomplete.autocomplete(parser, always_complete_options="long")
    return 0


def _graph_names(what: str) -> list[str]:
    """Names on the running graph; nothing when no graph runs (a Tab starts none)."""
    try:
        from launcher.bus import discovery, graph, keys
        from launcher.bus.session import open_session

        if not discovery.explicit_endpoints() and not discovery.answers(
                discovery.socket_path()):
            return []  # no graph: a Tab starts no router
        session = open_session("client")
        try:
            if what == "topics":
                return sorted(graph.topics(session))
            if what == "services":
                return sorted({e.topic for e in graph.entities(session)
                               if e.kind == keys.SERVICE})
            return sorted({e.node_fqn for e in graph.nodes(session)})
        finally:
            session.close()
    except Exception:  # noqa: BLE001 - completion offers what it can, never an error
        return []


def topics(prefix: str, **_: Any) -> list[str]:
    return [t for t in _graph_names("topics") if t.startswith(prefix)]


def services(prefix: str, **_: Any) -> list[str]:
    return [s for s in _graph_names("services") if s.startswith(prefix)]


def nodes(prefix: str, **_: Any) -> list[str]:
    return [n for n in _graph_names("nodes") if n.startswith(prefix)]


def packages(prefix: str, **_: Any) -> list[str]:
    try:
        from launcher.packages.index import PackageIndex

        return sorted(p.name for p in PackageIndex.from_environment()
                      if p.name.startswith(prefix))
    except Exception:  # noqa: BLE001 - completion offers what it can, never an error
        return []


def _package(name: str) -> Any:
    from launcher.packages.index import PackageIndex

    return PackageIndex.from_environment().get(name)


def executables(prefix: str, parsed_args: Any = None, **_: Any) -> list[str]:
    """The executables of the package typed before (`launcher run PKG <TAB>`)."""
    try:
        from launcher.packages.executables import executables as found

        return sorted(n for n in found(_package(parsed_args.package)) if n.startswith(prefix))
    except Exception:  # noqa: BLE001 - completion offers what it can, never an error
        return []


def launch_targets(prefix: str, **_: Any) -> list[str]:
    """`launcher launch <TAB>`: packages, and launch files here."""
    from pathlib import Path

    here = [str(p) for p in Path(".").glob(f"{prefix}*") if ".launch." in p.name or p.is_dir()]
    return sorted(packages(prefix)) + sorted(here)


def launch_files(prefix: str, parsed_args: Any = None, **_: Any) -> list[str]:
    """`launcher launch PKG <TAB>`: the package's launch files (then nothing: arguments)."""
    try:
        if parsed_args.arguments:
            return []
        package = _package(parsed_args.file)
        return sorted({p.name for p in package.path.rglob("*.launch.*")
                       if p.name.startswith(prefix)})
    except Exception:  # noqa: BLE001 - completion offers what it can, never an error
        return []
