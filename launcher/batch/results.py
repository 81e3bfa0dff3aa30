"""A job's result, as the driver keeps it and the reports read it."""

from __future__ import annotations

import enum
from typing import Any

from launcher import records


class Status(enum.Enum):
    PASS = "pass"  # every case passed / the launch ran to its planned stop
    FAIL = "fail"  # a case failed / a process exited non-zero
    ERROR = "error"  # the job could not run, or was lost after its retries
    TIMEOUT = "timeout"  # past its time limit; stopped
    CANCELLED = "cancelled"  # Ctrl-C of the batch


@records.dataclass(frozen=True)
class JobResult:
    id: str
    status: Status
    reason: str = ""  # why it did not pass, in words
    exit_code: int | None = None
    wall_s: float = 0.0  # the job's own wall time
    sim_s: float | None = None  # sim time reached (from the sim's report)
    rtf: float | None = None
    state: str | None = None  # the digest of the sim's state at its end
    node: str = ""  # the node's address
    started: float = 0.0  # time.time() at its start
    log: str = ""  # its folder among the results, relative to the run's folder
    cases: list[dict[str, Any]] = records.field(default_factory=list)  # {name, status, message}

    def to_json(self) -> dict[str, Any]:
        out = records.asdict(self)
        out["status"] = self.status.value
        return out

    @classmethod
    def from_json(cls, data: dict[str, Any]) -> JobResult:
        return cls(**{**data, "status": Status(data["status"])})
