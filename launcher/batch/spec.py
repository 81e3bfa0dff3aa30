"""What a batch file says, as records: each field declared once (docs/_gen builds the batch
file's reference page from these declarations)."""

from __future__ import annotations

from typing import Any

from launcher import records
from launcher.errors import Location
from launcher.schema import Attr, Kind, attr

DEFAULT_TIMEOUT = 600.0  # seconds per attempt of a job
KINDS = ("test", "launch")  # a job entry's kinds: its key names its file


def nested(factory: Any, doc: str) -> Any:
    """A field of nested YAML (a mapping or a list), read by load.py, declared for the docs."""
    return records.field(default_factory=factory, metadata={"launch": Attr(Kind.VALUE, doc=doc)})


@records.dataclass(frozen=True)
class Resources:
    """What one job needs of a node (Ray's resources)."""

    cpus: float = attr(Kind.FLOAT, 1.0, above=0, doc="CPUs (fractions allowed).")
    memory: str | None = attr(Kind.TEXT, doc="Memory: bytes, or a size like 512MiB or 2GiB.")
    gpus: float = attr(Kind.FLOAT, 0.0, minimum=0, doc="GPUs.")
    custom: dict[str, float] = nested(dict, "Custom resources of the cluster's nodes: "
                                            "name → amount.")


@records.dataclass(frozen=True)
class Stop:
    """How a launch job ends (a test ends itself)."""

    duration: float | None = None  # wall seconds
    sim_duration: float | None = None  # seconds of sim time
    until: str | None = None  # that process's exit


@records.dataclass(frozen=True)
class Entry:
    """One item of `jobs:`: a launch test or a launch file, with what it alone sets."""

    test: str | None = attr(Kind.TEXT, doc="A launch test (launch_testing or launch_pytest "
                                           ".py) or a rostest file (.test).")
    launch: str | None = attr(Kind.TEXT, doc="A launch file, run for `duration`, "
                                             "`sim_duration` or `until`.")
    package: str | None = attr(Kind.NAME, doc="The package the file is in (as `launcher "
                                              "launch PKG FILE`).")
    name: str | None = attr(Kind.NAME, doc="The job's label (default: the file's stem).")
    arguments: dict[str, str] = nested(dict, "Fixed launch arguments of this job.")
    matrix: dict[str, list[str]] = nested(dict, "This job's own matrix keys (over the "
                                                "batch's; its keys win).")
    duration: float | None = attr(Kind.FLOAT, above=0, doc="Wall seconds a launch job runs.")
    sim_duration: float | None = attr(Kind.FLOAT, above=0,
                                      doc="Seconds of sim time a launch job runs.")
    until: str | None = attr(Kind.NAME, doc="The process whose exit ends a launch job.")
    timeout: float | None = attr(Kind.FLOAT, above=0, doc="Seconds per attempt (over the "
                                                          "batch's).")
    retries: int | None = attr(Kind.INT, minimum=0, doc="Attempts more after a lost worker "
                                                        "(over the batch's).")
    resources: Resources | None = attr(Kind.VALUE, doc="What the job needs (over the "
                                                       "batch's).")
    lockstep: bool | None = attr(Kind.BOOL, doc="Lockstep on or off (over the batch's).")
    env: dict[str, str] = nested(dict, "Environment variables (over the batch's).")
    where: Location | None = None  # the entry in the batch file
    places: dict[str, Location] = records.field(default_factory=dict)  # its keys' values

    @property
    def kind(self) -> str:
        return "test" if self.test is not None else "launch"

    @property
    def file(self) -> str:
        return self.test if self.test is not None else str(self.launch)

    @property
    def stop(self) -> Stop:
        return Stop(self.duration, self.sim_duration, self.until)


@records.dataclass(frozen=True)
class BatchFile:
    """A whole batch file."""

    jobs: list[Entry] = nested(list, "The jobs (required): each a `test:` or a "
                                                            "`launch:`, at least one.")
    name: str | None = attr(Kind.NAME, doc="The batch's name (default: the file's stem).")
    matrix: dict[str, list[str]] = nested(dict, "Launch arguments: every "
                                                        "combination runs.")
    seeds: list[int] = nested(lambda: [0], "A count (10: seeds 0-9) or a list of seeds; "
                                            "default [0].")
    repeats: int = attr(Kind.INT, 1, minimum=1, doc="Runs of each combination and seed.")
    lockstep: bool | None = attr(Kind.BOOL, doc="Lockstep on or off for every job (unset: "
                                                "each file decides).")
    timeout: float = attr(Kind.FLOAT, DEFAULT_TIMEOUT, above=0, doc="Seconds per attempt "
                                                                     "of a job.")
    retries: int = attr(Kind.INT, 0, minimum=0, doc="Attempts more after a lost worker or "
                                                    "node.")
    resources: Resources = nested(Resources, "What each job needs of a node "
                                                "(default: 1 CPU).")
    env: dict[str, str] = nested(dict, "Environment variables of every job.")
    workspace: str | None = attr(Kind.TEXT, doc="The folder that travels to a cluster "
                                                "(default: the batch file's folder).")
    shared_workspace: bool = attr(Kind.BOOL, False, doc="true: the workspace is at the same "
                                                        "path on every node, not uploaded.")
    package_path: list[str] = attr(Kind.NAMES, doc="Folders of packages (in the workspace) "
                                                   "every job finds.")
    exclude: list[str] = attr(Kind.NAMES, doc="Left out of the upload, beside .gitignore "
                                              "and .rayignore.")
    path: Any = None  # the batch file (a Path)
    places: dict[str, Location] = records.field(default_factory=dict)

    @property
    def title(self) -> str:
        return self.name or self.path.name.split(".")[0]
