"""roslaunch's Python API over launcher: ROS 1 scripts and tests that drive roslaunch from
Python (`roslaunch.parent.ROSLaunchParent`, `roslaunch.scriptapi.ROSLaunch`,
`roslaunch.rlutil`, `roslaunch.substitution_args`, configs loaded by `XmlLoader`) run
unchanged: the files are read by launcher's ROS 1 frontend and run by its runtime on the
user's graph. ROS 1's XML-RPC machinery (the launch server, remote children over SSH, the
master) is not here. A real roslaunch that the user installed wins."""

from __future__ import annotations

import logging
import os
import socket
import sys
from typing import Any

from roslaunch import core as roslaunch_core
from roslaunch.config import ROSLaunchConfig  # noqa: F401 (roslaunch has these)
from roslaunch.core import Master, Node, RLException, Test  # noqa: F401
from roslaunch.launch import (  # noqa: F401
    DEFAULT_TIMEOUT_SIGINT,
    DEFAULT_TIMEOUT_SIGTERM,
    NUM_WORKERS,  # noqa: F401
)
from roslaunch.pmon import Process  # noqa: F401
from roslaunch.rlutil import DEFAULT_MASTER_PORT  # noqa: F401
from roslaunch.scriptapi import ROSLaunch  # noqa: F401
from roslaunch.xmlloader import XmlLoader, XmlParseException  # noqa: F401

NAME = "roslaunch"


def configure_logging(uuid: str) -> None:
    """Log roslaunch's messages (printlog, printerrlog) to a file of run `uuid`, below
    launcher's log folder."""
    from launcher.runtime.logs import log_root

    folder = log_root() / str(uuid)
    try:
        folder.mkdir(parents=True, exist_ok=True)
        path = folder / f"{NAME}-{socket.gethostname()}-{os.getpid()}.log"
        handler = logging.FileHandler(path, encoding="utf-8")
    except OSError:
        print("WARNING: unable to configure logging. No log files will be generated",
              file=sys.stderr)
        return
    handler.setFormatter(logging.Formatter("[%(name)s][%(levelname)s] %(asctime)s: "
                                           "%(message)s"))
    logger = logging.getLogger("roslaunch")
    logger.addHandler(handler)
    logger.setLevel(logging.INFO)
    print(f"... logging to {path}")
    roslaunch_core.add_printlog_handler(logger.info)
    roslaunch_core.add_printerrlog_handler(logger.error)


def write_pid_file(options_pid_fn: str | None, options_core: bool, port: int | None) -> None:
    """Write this process's pid to `options_pid_fn` (roscore's: ROS_HOME/roscore-PORT.pid)."""
    if not (options_pid_fn or options_core):
        return
    if options_pid_fn:
        path = os.path.expanduser(options_pid_fn)
    else:
        home = os.environ.get("ROS_HOME") or os.path.join(os.path.expanduser("~"), ".ros")
        path = os.path.join(home, f"roscore-{port or DEFAULT_MASTER_PORT}.pid")
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w", encoding="utf-8") as handle:
        handle.write(str(os.getpid()))


def handle_exception(roslaunch_core: Any, logger: Any, msg: str, e: BaseException) -> None:
    """Print `msg` and `e` as roslaunch's error, log it, and exit with status 1."""
    roslaunch_core.printerrlog(f"{msg}{e}")
    roslaunch_core.printerrlog("The traceback for the exception was written to the log file")
    if logger is not None:
        logger.error(str(e))
    sys.exit(1)


def main(argv: list[str] = sys.argv) -> None:  # noqa: B006 (roslaunch's)
    """`roslaunch ARGS…` (argv[0] is the program): launcher's roslaunch command."""
    from launcher.cli.main import run_tool

    sys.exit(run_tool("roslaunch", list(argv[1:])))


from launcher.compat.finder import rest_from_layout  # noqa: E402 - the rest of the real module's names

__getattr__ = rest_from_layout(__name__)
