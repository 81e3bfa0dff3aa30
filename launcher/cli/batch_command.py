"""`launcher batch FILE`: launch tests and launch files over a matrix of launch arguments,
seeds and repeats, each job on a graph of its own; here, on Ray started for the batch, or on
a running Ray cluster (`--address`, RAY_ADDRESS). Exit status: 0 when every job passed, 1
otherwise, 130 after Ctrl-C (143 after SIGTERM)."""

from __future__ import annotations

import argparse
import importlib.util
import json
import os
import subprocess
import sys
from pathlib import Path
from typing import Any

from launcher import __version__
from launcher.batch.checks import check_entries
from launcher.batch.job import JobSpec
from launcher.batch.load import load_batch
from launcher.batch.matrix import JobPlan, Overrides, expand, parse_only, parse_pairs, select
from launcher.batch.runner import Job
from launcher.batch.spec import BatchFile
from launcher.batch.store import ResultsStore
from launcher.batch.workspace import Workspace, plan_workspace
from launcher.cli.launch_command import parse_assignments
from launcher.errors import LaunchError, UsageError

INSPECT_SECONDS = 120.0  # for reading what the job files declare


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.description = (
        "Run launch tests and launch files over a matrix of arguments, seeds and repeats, "
        "each job on a graph of its own: here (Ray started for the batch, every core) or on "
        "a Ray cluster. Exit status: 0 when every job passed, 1 otherwise, 130 after Ctrl-C.")
    parser.add_argument("file", metavar="FILE", help="the batch file (YAML)")
    parser.add_argument("assignments", nargs="*", metavar="name:=value",
                        help="a launch argument fixed for every job (replaces a matrix key)")
    parser.add_argument("--address", default=None, metavar="ADDR",
                        help="a running Ray cluster: HOST:PORT, ray://HOST:PORT or auto "
                             "(default: RAY_ADDRESS, else Ray started here for the batch)")
    parser.add_argument("--matrix", action="append", default=[], metavar="NAME=VALUE",
                        help="add a matrix key, or replace its values (repeat for more)")
    parser.add_argument("--only", action="append", default=[], metavar="NAME=VALUE",
                        help="run only the jobs whose NAME (a matrix key, seed, repeat or "
                             "job) is VALUE (repeat: any of them)")
    parser.add_argument("--rerun-failed", action="store_true",
                        help="run only the jobs that did not pass in the last run")
    parser.add_argument("--junit-xml", default=None, metavar="PATH",
                        help="also write the results as JUnit XML here")
    parser.add_argument("--csv", default=None, metavar="PATH",
                        help="also write every job's row as CSV here")
    parser.add_argument("--results", default=None, metavar="DIR",
                        help="where runs are kept (default: batch-results/NAME beside FILE)")
    parser.add_argument("--list", action="store_true", help="list the jobs and exit")
    parser.add_argument("-n", "--noninteractive", action="store_true",
                        help="a line per job, not a bar redrawn in place")


def run(args: argparse.Namespace) -> int:
    batch = load_batch(Path(args.file))
    overrides = Overrides(parse_assignments(args.assignments), parse_pairs(args.matrix, "--matrix"))
    facts = _inspect(batch)
    for warning in check_entries(batch, overrides, facts):
        print(f"warning: {warning}", file=sys.stderr)
    store = ResultsStore(Path(args.results) if args.results else
                         batch.path.parent / "batch-results" / batch.title, batch)
    rerun = store.last_failures() if args.rerun_failed else None
    if rerun == set():
        print("--rerun-failed: every job of the last run passed; nothing to run",
              file=sys.stderr)
        return 0
    plans = select(expand(batch, overrides), parse_only(args.only), rerun)
    if not plans:
        raise UsageError("no job is left to run: --only keeps none"
                         + (" of the last run's failures" if rerun else ""))
    if args.list:
        for plan in plans:
            print(f"{plan.id}  {plan.title}")
        return 0
    _need_ray()
    address = args.address or os.environ.get("RAY_ADDRESS") or None
    workspace = plan_workspace(batch, remote=address is not None)
    jobs = [_job(batch, plan, facts[plan.number], workspace) for plan in plans]
    from launcher.cli.batch_run import run_batch

    return run_batch(batch, jobs, store, address, workspace, args)


def _inspect(batch: BatchFile) -> list[dict[str, Any]]:
    """What each entry's file declares, read by a child (launcher.cli.batch_inspect)."""
    requests = [{"path": str(batch.path.parent / e.file) if not e.package else e.file,
                 "test": e.kind == "test", "package": e.package} for e in batch.jobs]
    try:
        done = subprocess.run([sys.executable, "-m", "launcher.cli.batch_inspect"],
                              input=json.dumps(requests), capture_output=True, text=True,
                              check=False, timeout=INSPECT_SECONDS)
    except subprocess.TimeoutExpired:
        raise LaunchError(f"the job files could not be read within {INSPECT_SECONDS:g} s "
                          "(a test module that waits as it is imported?): "
                          f"{', '.join(e.file for e in batch.jobs)}") from None
    try:
        return json.loads(done.stdout)
    except ValueError:
        why = done.stderr.strip().splitlines()[-1:] or [f"exit code {done.returncode}"]
        raise LaunchError(f"the job files could not be read: {why[0]}") from None


def _need_ray() -> None:
    """Ray is installed, new enough (not imported: it reads its settings at import, which
    the cluster sets first)."""
    from importlib import metadata

    advice = (f"launcher batch runs its jobs on Ray, which is not installed for "
              f"{sys.executable}: pip install 'launcher[cluster]'")
    try:
        version = metadata.version("ray") if importlib.util.find_spec("ray") else None
    except (metadata.PackageNotFoundError, ImportError, ValueError):
        version = None
    if version is None:
        raise LaunchError(advice)
    major, minor = (int(part) for part in version.split(".")[:2])
    if (major, minor) < (2, 60):
        raise LaunchError(f"Ray {version} is installed; launcher batch needs Ray 2.60 or "
                          "newer: pip install -U 'launcher[cluster]'")


def _spec(batch: BatchFile, plan: JobPlan, fact: dict[str, Any],
          workspace: Workspace) -> JobSpec:
    entry = plan.entry
    lockstep = entry.lockstep if entry.lockstep is not None else batch.lockstep
    arguments = dict(plan.arguments)
    if "seed" in fact["arguments"]:
        arguments.setdefault("seed", str(plan.seed))
    if lockstep and "use_sim_time" in fact["arguments"]:
        arguments.setdefault("use_sim_time", "true")
    return JobSpec(
        batch=batch.title, id=plan.id, title=plan.title, kind=fact["kind"],
        file=workspace.job_file(batch, entry), arguments=arguments, seed=plan.seed,
        timeout=entry.timeout if entry.timeout is not None else batch.timeout,
        package=entry.package, repeat=plan.repeat, lockstep=lockstep,
        stop={"duration": entry.duration, "sim_duration": entry.sim_duration,
              "until": entry.until},
        env={**batch.env, **entry.env}, package_path=list(batch.package_path),
        root=workspace.spec_root, launcher_version=__version__)


def _job(batch: BatchFile, plan: JobPlan, fact: dict[str, Any], workspace: Workspace) -> Job:
    entry = plan.entry
    return Job(plan, _spec(batch, plan, fact, workspace), entry.resources or batch.resources,
               entry.retries if entry.retries is not None else batch.retries)
