"""The router of a run: `python -m launcher.bus.router --listen tcp/127.0.0.1:PORT`.

`--connect` joins other routers (another host's launch): routers connect to routers.
It runs until SIGINT or SIGTERM.
"""

from __future__ import annotations

import argparse
import signal
import sys
import threading

import zenoh

from launcher.bus.session import config


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="launcher-router")
    parser.add_argument("--listen", action="append", default=[], metavar="ENDPOINT")
    parser.add_argument("--connect", action="append", default=[], metavar="ENDPOINT")
    args = parser.parse_args(argv)
    stop = threading.Event()
    for sig in (signal.SIGINT, signal.SIGTERM):
        signal.signal(sig, lambda *_: stop.set())
    session = zenoh.open(config("router", args.listen or ["tcp/127.0.0.1:0"], args.connect))
    print(f"router {session.zid()} listening on {', '.join(args.listen)}", flush=True)
    stop.wait()
    session.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
