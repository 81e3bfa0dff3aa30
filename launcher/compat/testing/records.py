"""What the test runner records of a test's processes: each start and exit, each piece of
output, keyed by the launch action that started the process (as launch's events are)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any


@dataclass
class ProcessInfo:
    """A process that started (`returncode` None) or ended."""
    action: Any
    process_name: str
    cmd: list[str]
    pid: int | None
    returncode: int | None = None

    @property
    def exited(self) -> bool:
        return self.returncode is not None


@dataclass
class ProcessOutput:
    """A piece of a process's output (`text` as bytes, as launch's ProcessIO has it)."""
    action: Any
    process_name: str
    text: bytes
    stream: str  # stdout | stderr

    @property
    def from_stdout(self) -> bool:
        return self.stream == "stdout"

    @property
    def from_stderr(self) -> bool:
        return self.stream == "stderr"
