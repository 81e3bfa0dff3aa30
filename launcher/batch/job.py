"""What a job is on the node that runs it: its spec (sent as JSON from the driver), its
folder, its command line and its environment. Standard library only: every job pays for the
job host's imports."""

from __future__ import annotations

import json
import os
import shutil
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

PROTOCOL = 1  # the spec's shape; a node with another launcher says so rather than guess
JOB_MARK_PREFIX = "LAUNCHER_BATCH_JOB_"  # kept by `detached()` processes (a job's router)
SEED_VARIABLE = "LAUNCHER_BATCH_SEED"
JOB_VARIABLE = "LAUNCHER_BATCH_JOB"
OUTPUT_VARIABLE = "LAUNCHER_BATCH_OUTPUT"
SCRATCH_VARIABLE = "LAUNCHER_BATCH_SCRATCH"  # the task's folder for the job (removed after)
SCRATCH_PREFIX = "lnb-"  # (a task's folder, which the next task removes if its worker died)
OWNER = "owner"  # in such a folder: the pid of the process that made it
ORPHANED = 600.0  # seconds after which such a folder without its OWNER is removed
# what a node's environment must not hand a job: another graph, Ray's own settings
_NOT_PASSED = ("LAUNCHER_ROUTER", "LAUNCHER_RUN_DIR", "RAY_ADDRESS", "ROS_LOG_DIR",
               "LAUNCHER_BATCH_SCRATCH",
               "LAUNCHER_LOG_DIR", "LAUNCHER_SIM_STOP_AT", "LAUNCHER_SIM_REPORT_DIR")


@dataclass
class JobSpec:
    batch: str  # the batch's title
    id: str
    title: str  # drive[world=a.sdf, seed=3]
    kind: str  # test (launch_testing), pytest (launch_pytest), rostest, launch
    file: str  # relative to the workspace root, or absolute
    arguments: dict[str, str]
    seed: int
    timeout: float
    package: str | None = None
    repeat: int = 0
    lockstep: bool | None = None
    stop: dict[str, Any] = field(default_factory=dict)  # duration, sim_duration, until
    env: dict[str, str] = field(default_factory=dict)
    package_path: list[str] = field(default_factory=list)  # relative to the root
    root: str = ""  # the workspace root: "" means the task's working folder (an upload)
    launcher_version: str = ""
    protocol: int = PROTOCOL

    def to_json(self) -> str:
        return json.dumps(asdict(self))

    @classmethod
    def from_json(cls, text: str) -> JobSpec:
        return cls(**json.loads(text))


@dataclass(frozen=True)
class JobFolder:
    """Where a job keeps what comes back to the driver."""

    root: Path

    @property
    def output(self) -> Path:  # files the job puts there come back
        return self.root / "output"

    @property
    def log(self) -> Path:  # ROS_LOG_DIR, the launch's logs
        return self.root / "log"

    @property
    def sim(self) -> Path:  # the sims' reports
        return self.root / "sim"

    @property
    def console(self) -> Path:  # the job's stdout and stderr
        return self.root / "output.log"

    @property
    def junit(self) -> Path:
        return self.root / "junit.xml"

    def make(self) -> None:
        for folder in (self.root, self.output, self.log, self.sim):
            folder.mkdir(mode=0o700, parents=True, exist_ok=True)


def command(spec: JobSpec, folder: JobFolder, python: str, root: Path) -> list[str]:
    """The job's command line: launcher's own commands, as a user runs them."""
    file = spec.file if spec.package else str(root / spec.file)  # (a package's: found there)
    words = [f"{k}:={v}" for k, v in spec.arguments.items()]
    if spec.kind == "test":
        return [python, "-m", "launcher", "test", file, *words, "--package-name", spec.batch,
                "--junit-xml", str(folder.junit)]
    if spec.kind == "pytest":
        return [python, "-m", "pytest", "-q", "-p", "no:cacheprovider", file,
                f"--junit-xml={folder.junit}", "--launch-args", *words]
    if spec.kind == "rostest":
        return [python, "-m", "launcher", "rostest", file, *words, "--results-base-dir",
                str(folder.root / "rostest")]
    argv = [python, "-m", "launcher", "launch", *([spec.package] if spec.package else []),
            file, *words, "--noninteractive"]
    for key in ("duration", "sim_duration", "until"):
        if spec.stop.get(key) is not None:
            argv += [f"--{key.replace('_', '-')}", str(spec.stop[key])]
    return argv


def environment(spec: JobSpec, base: dict[str, str], folder: JobFolder, run_dir: str,
                root: Path, mark: str) -> dict[str, str]:
    """The job's environment: the node's, less what belongs to another graph or to Ray, plus
    the job's own graph, folders, seed and the batch's settings."""
    env = {k: v for k, v in base.items() if k not in _NOT_PASSED and not k.startswith("RAY_")}
    paths = [str(root / p) for p in spec.package_path]
    if env.get("LAUNCHER_PACKAGE_PATH"):
        paths.append(env["LAUNCHER_PACKAGE_PATH"])
    env.update({
        "LAUNCHER_RUN_DIR": run_dir, "LAUNCHER_ROUTER_LINGER": "0",
        "LAUNCHER_LOG_DIR": str(folder.log), "ROS_LOG_DIR": str(folder.log),
        "LAUNCHER_SIM_REPORT_DIR": str(folder.sim), "LAUNCHER_SIM_SEED": str(spec.seed),
        SEED_VARIABLE: str(spec.seed), JOB_VARIABLE: spec.id,
        OUTPUT_VARIABLE: str(folder.output), "PYTHONUNBUFFERED": "1", mark: "1"})
    if paths:
        env["LAUNCHER_PACKAGE_PATH"] = os.pathsep.join(paths)
    if spec.lockstep is not None:
        env["LAUNCHER_SIM_LOCKSTEP"] = "true" if spec.lockstep else "false"
    if spec.lockstep:
        env["PYTHONHASHSEED"] = "0"  # a repeatable run needs a fixed hash order
    env.update(spec.env)
    return env


def sweep_stale(where: Path, prefix: str) -> list[Path]:
    """Remove the folders `prefix*` in `where` whose owner is gone without removing them (a
    SIGKILL): this user's, whose owner's pid (the file OWNER in it) no longer runs; or that
    have lost their OWNER for ORPHANED seconds (a removal cut short by what still wrote in
    it: OWNER is written as the folder is made)."""
    removed = []
    for folder in where.glob(f"{prefix}*"):
        stat = None
        try:
            stat = folder.stat()
            if stat.st_uid != os.getuid():
                continue
            pid = int((folder / OWNER).read_text())
        except FileNotFoundError:
            if stat is not None and folder.is_dir() and time.time() - stat.st_mtime > ORPHANED:
                shutil.rmtree(folder, ignore_errors=True)
                removed.append(folder)
            continue
        except (OSError, ValueError):
            continue
        try:
            os.kill(pid, 0)
            continue  # (still running: its batch's)
        except ProcessLookupError:
            pass
        except PermissionError:
            continue
        shutil.rmtree(folder, ignore_errors=True)
        removed.append(folder)
    return removed
