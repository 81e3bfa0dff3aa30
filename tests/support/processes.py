"""The real CLI's command line, and the processes a test started (found by their tag).

Every launcher started by a test carries a unique LAUNCHER_TEST_TAG in its environment, which
its children and grandchildren inherit; after the test, no process may still carry it.
"""

from __future__ import annotations

import sys
from pathlib import Path

import psutil


def launcher_argv() -> list[str]:
    exe = Path(sys.executable).with_name("launcher")
    return [str(exe)] if exe.exists() else [sys.executable, "-m", "launcher"]


def tagged_processes(tag: str) -> list[psutil.Process]:
    found = []
    for proc in psutil.process_iter(["pid"]):
        try:
            if proc.environ().get("LAUNCHER_TEST_TAG") == tag and \
                    proc.status() != psutil.STATUS_ZOMBIE:
                found.append(proc)
        except (psutil.NoSuchProcess, psutil.AccessDenied, psutil.ZombieProcess):
            continue
    return found


def is_router(proc: psutil.Process) -> bool:
    """The graph's router: started detached, the one process meant to outlive launches."""
    try:
        return "launcher.bus.router" in proc.cmdline()
    except psutil.Error:
        return False


def end_lingering_routers(processes: list[psutil.Process]) -> None:
    """The graph's router outlives its last user by LAUNCHER_ROUTER_LINGER, on purpose (the
    next command of a shell finds it up; test_bus checks that it then goes by itself). The
    test is over: it is asked to go now (SIGTERM, its own clean stop), not waited for."""
    for proc in processes:
        try:
            if "launcher.bus.router" in proc.cmdline():
                proc.terminate()
        except psutil.Error:
            continue


def describe(proc: psutil.Process) -> str:
    try:
        return f"{proc.pid} {' '.join(proc.cmdline())}"
    except psutil.Error:
        return f"{proc.pid} (gone or a zombie)"
