"""A job's result from what it left: its exit status, its JUnit or rostest XML, the
reporter's `error:` line in its output, the sims' reports, and why the host stopped it."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ElementTree
from pathlib import Path
from typing import Any, NamedTuple

from launcher.batch.job import JobFolder, JobSpec
from launcher.batch.results import JobResult, Status

STOPS = {"timeout": Status.TIMEOUT, "cancelled": Status.CANCELLED}


class Ending(NamedTuple):
    """How the job's process ended, as the host saw it."""

    exit_code: int
    stopped_for: str | None  # timeout, cancelled, lost, SIGTERM…; None: it ended itself
    wall_s: float
    started: float
    leftovers: list[str]  # processes still carrying the job's mark after it ended


def judge(spec: JobSpec, folder: JobFolder, ending: Ending) -> JobResult:
    cases = read_cases(folder)
    sims = read_sim_reports(folder.sim)
    status, reason = _status(spec, folder, ending, cases)
    if ending.leftovers and status is Status.PASS:
        reason = f"left {', '.join(ending.leftovers)} running; ended by the batch"
    first = sims[0] if sims else {}
    return JobResult(spec.id, status, reason, ending.exit_code, round(ending.wall_s, 3),
                     first.get("sim_time"), first.get("rtf"), first.get("state"),
                     started=ending.started, cases=cases)


def _status(spec: JobSpec, folder: JobFolder, ending: Ending,
            cases: list[dict[str, Any]]) -> tuple[Status, str]:
    if ending.stopped_for is not None:
        status = STOPS.get(ending.stopped_for, Status.ERROR)
        if status is Status.TIMEOUT:
            return status, f"ran past its time limit of {spec.timeout:g} s; stopped"
        if status is Status.CANCELLED:
            return status, "cancelled"
        return status, f"stopped: {ending.stopped_for}"
    failed = [c for c in cases if c["status"] in ("failure", "error")]
    if failed:
        return Status.FAIL, f"{failed[0]['name']}: {failed[0]['message']}".strip(": ")
    error = _error_line(folder.console)
    if spec.kind != "launch":
        if ending.exit_code == 0 and cases:
            return Status.PASS, ""
        if error:
            return Status.ERROR, error
        if not cases:
            return Status.ERROR, f"no test ran (exit code {ending.exit_code})"
        return Status.FAIL, f"exit code {ending.exit_code}"
    if ending.exit_code == 0:
        return Status.PASS, ""
    if error:
        return Status.ERROR, error
    return Status.FAIL, _last_line(folder.console) or f"exit code {ending.exit_code}"


def read_cases(folder: JobFolder) -> list[dict[str, Any]]:
    """Every test case of the job's JUnit XML files (launch_testing's, pytest's, rostest's)."""
    files = [folder.junit] if folder.junit.is_file() else []
    files += sorted((folder.root / "rostest").rglob("*.xml"))
    cases = []
    for file in files:
        try:
            tree = ElementTree.parse(file)
        except (ElementTree.ParseError, OSError):
            continue
        for case in tree.iter("testcase"):
            status, message = "passed", ""
            for kind in ("failure", "error", "skipped"):
                found = case.find(kind)
                if found is not None:
                    status, message = kind, (found.get("message") or found.text or "")
                    break
            cases.append({"name": case.get("name", ""), "status": status,
                          "message": message.strip().splitlines()[0] if message.strip()
                          else ""})
    return cases


def read_sim_reports(folder: Path) -> list[dict[str, Any]]:
    reports = []
    for file in sorted(folder.glob("sim-*.json")):
        try:
            reports.append(json.loads(file.read_text()))
        except (OSError, ValueError):
            continue
    return reports


def _tail(console: Path, size: int = 65536) -> list[str]:
    try:
        with open(console, "rb") as f:
            f.seek(max(0, f.seek(0, 2) - size))
            return f.read().decode("utf-8", "replace").splitlines()
    except OSError:
        return []


def _error_line(console: Path) -> str:
    """launcher's reporter's last `error: …` line, else the launch's first error (a launch
    file that fails as it runs: a package not found on this node)."""
    lines = _tail(console)
    found = [line for line in lines if line.startswith("error: ")]
    if found:
        return found[-1][len("error: "):]
    launch = [line for line in lines if line.startswith("[ERROR] [launch]: ")]
    return launch[0][len("[ERROR] [launch]: "):] if launch else ""


def _last_line(console: Path) -> str:
    lines = [line for line in _tail(console) if line.strip()]
    return lines[-1].strip() if lines else ""
