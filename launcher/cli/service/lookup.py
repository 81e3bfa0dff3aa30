"""The services a `service` verb finds on the graph."""

from __future__ import annotations

import argparse

from launcher.bus import graph, keys
from launcher.bus.session import open_session
from launcher.cli.graph_options import space_of
from launcher.errors import LaunchError, did_you_mean


def graph_services(args: argparse.Namespace) -> list[keys.Entity]:
    session = open_session("client")
    found = [e for e in graph.entities(session, space=space_of(args))
             if e.kind in (keys.SERVICE, keys.CLIENT)]
    session.close()
    return found


def named_service(args: argparse.Namespace) -> list[keys.Entity]:
    found = graph_services(args)
    mine = [e for e in found if e.topic == args.name]
    if not any(e.kind == keys.SERVICE for e in mine):
        known = sorted({e.topic for e in found if e.kind == keys.SERVICE})
        raise LaunchError(f"unknown service '{args.name}'{did_you_mean(args.name, known)}")
    return mine
