"""`launcher router [--listen ENDPOINT …]`: a standing router of the user's graph."""

from __future__ import annotations

import argparse


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.description = (
        "Run the router of this user's graph (ROS_DOMAIN_ID) until Ctrl-C. Launches start one "
        "themselves when none runs, and it stops a few seconds after the last of them; this "
        "one stays. With --listen tcp/0.0.0.0:7447 other hosts join: they set "
        "LAUNCHER_ROUTER=tcp/<this host>:7447 and need a copy of ~/.launcher/credentials "
        "(every link is authenticated).")
    parser.add_argument("--listen", action="append", default=[], metavar="ENDPOINT",
                        help="also listen here, e.g. tcp/0.0.0.0:7447 (repeatable)")


def run(args: argparse.Namespace) -> int:
    import signal
    import threading

    from launcher.bus.router import serve

    stop = threading.Event()
    for sig in (signal.SIGINT, signal.SIGTERM):
        signal.signal(sig, lambda *_: stop.set())
    return serve(args.listen, None, None, stop)
