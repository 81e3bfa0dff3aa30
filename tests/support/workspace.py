"""A temporary folder to write launch files into and run the real `launcher` against."""

from __future__ import annotations

import os
import subprocess
import textwrap
import time
from pathlib import Path

import psutil

from tests.support.processes import launcher_argv, tagged_processes


class Workspace:
    """A temporary folder to write launch files into and run `launcher` against."""

    def __init__(self, root: Path, tag: str) -> None:
        self.root = root
        self.tag = tag
        # A graph of the test's own (its run folder), whose router stops half a second after
        # its last user instead of three: the leak check of the `ws` fixture waits for it to go.
        self.env = dict(os.environ, LAUNCHER_TEST_TAG=tag,
                        LAUNCHER_LOG_DIR=str(root / "log"), PYTHONUNBUFFERED="1",
                        LAUNCHER_RUN_DIR=str(root / "run"), LAUNCHER_ROUTER_LINGER="0.5")

    def own_bus(self) -> Workspace:
        """Launches and tools started here meet only each other (the run folder of this
        test's), with no router or simulator paths from outside."""
        for name in ("LAUNCHER_ROUTER", "MUJOCO_SIM_RESOURCE_PATH", "MUJOCO_SIM_PLUGIN_PATH",
                     "GZ_SIM_RESOURCE_PATH", "IGN_GAZEBO_RESOURCE_PATH", "GAZEBO_MODEL_PATH",
                     "GAZEBO_RESOURCE_PATH", "GZ_SIM_SYSTEM_PLUGIN_PATH", "GAZEBO_PLUGIN_PATH"):
            self.env.pop(name, None)
        return self

    def write(self, name: str, text: str) -> Path:
        path = self.root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(textwrap.dedent(text).lstrip("\n"))
        return path

    def run(self, *args: str, timeout: float = 60, **kwargs) -> subprocess.CompletedProcess:
        """Run `launcher ARGS…` to completion."""
        return subprocess.run(launcher_argv() + list(args), cwd=self.root, env=self.env,
                              capture_output=True, text=True, timeout=timeout, **kwargs)

    def start(self, *args: str, output: str = "stdout.txt",
              env: dict[str, str] | None = None) -> subprocess.Popen:
        """Start `launcher ARGS…` in the background: stdout to `output`, stderr to
        stderr.txt (or to `output` too when it is not the default)."""
        out = open(self.root / output, "w")  # noqa: SIM115
        err = open(self.root / "stderr.txt", "w") if output == "stdout.txt" \
            else subprocess.STDOUT  # noqa: SIM115
        return subprocess.Popen(launcher_argv() + list(args), cwd=self.root,
                                env={**self.env, **(env or {})}, stdout=out, stderr=err,
                                text=True)

    def output(self, name: str = "stdout.txt") -> str:
        return (self.root / name).read_text()

    def wait_for_output(self, needle: str, timeout: float = 30,
                        name: str = "stdout.txt") -> str:
        """The output file `name` once it holds `needle` (fails after `timeout` seconds)."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            text = self.output(name)
            if needle in text:
                return text
            time.sleep(0.02)
        raise AssertionError(f"{needle!r} not in output:\n{self.output(name)}")

    def processes(self) -> list[psutil.Process]:
        return tagged_processes(self.tag)
