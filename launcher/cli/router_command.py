"""`launcher router [--listen ENDPOINT …] [--join ENDPOINT]`: a standing router of the user's
graph, or a bridge joining it to another host's."""

from __future__ import annotations

import argparse


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.description = (
        "Run the router of this user's graph (ROS_DOMAIN_ID) until Ctrl-C. Launches start one "
        "themselves when none runs, and it stops a few seconds after the last of them; this "
        "one stays. With --listen tcp/0.0.0.0:7447 other hosts join: they set "
        "LAUNCHER_ROUTER=tcp/<this host>:7447, or run `launcher router --join "
        "tcp/<this host>:7447` there, and need a copy of ~/.launcher/credentials (every link "
        "is authenticated). With --join this host's graph joins that one: what runs here, "
        "and every shell here, sees the nodes of both.")
    parser.add_argument("--listen", action="append", default=[], metavar="ENDPOINT",
                        help="also listen here, e.g. tcp/0.0.0.0:7447 (repeatable)")
    parser.add_argument("--join", metavar="ENDPOINT", default=None,
                        help="join this host's graph to another host's router listening there "
                             "(its --listen), e.g. tcp/192.168.1.5:7447; says one line once "
                             "joined, and ends on Ctrl-C or when its stdin (a pipe) closes")


def run(args: argparse.Namespace) -> int:
    import signal
    import threading

    from launcher.bus import router

    stop = threading.Event()
    for sig in (signal.SIGINT, signal.SIGTERM):
        signal.signal(sig, lambda *_: stop.set())
    return router.run(args.listen, args.join, stop)
