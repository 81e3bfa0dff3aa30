"""How a batch's workspace reaches the nodes: used in place on this machine, uploaded through
Ray's runtime environment to a cluster, or found at the same path on a shared filesystem."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from launcher import records
from launcher.batch.spec import BatchFile, Entry
from launcher.errors import ParseError

# never uploaded, beside what .gitignore and .rayignore leave out (Ray reads both)
DEFAULT_EXCLUDES = (".git/", ".venv/", "batch-results/", "__pycache__/", "*.pyc", "build/",
                    "log/")


@records.dataclass(frozen=True)
class Workspace:
    root: Path
    mode: str  # local, upload or shared

    def job_file(self, batch: BatchFile, entry: Entry) -> str:
        """The entry's file as the job host finds it: relative to the root where it is inside
        it (absolute otherwise, which only a workspace in place or shared allows)."""
        if entry.package:
            return entry.file  # found by its package on the node
        file = (batch.path.parent / entry.file).resolve()
        if file.is_relative_to(self.root):
            return str(file.relative_to(self.root))
        if self.mode == "upload":
            raise ParseError(f"{entry.kind}: {file} is outside the workspace {self.root} "
                             "that travels to the cluster: move it in, set workspace:, or "
                             "share it (shared_workspace: true)", entry.places.get(entry.kind))
        return str(file)

    @property
    def spec_root(self) -> str:
        """The root a job host is told: none for an upload (Ray's copy is its working
        folder)."""
        return "" if self.mode == "upload" else str(self.root)

    def runtime_env(self, batch: BatchFile) -> dict[str, Any] | None:
        if self.mode != "upload":
            return None
        return {"working_dir": str(self.root), "excludes": [*DEFAULT_EXCLUDES, *batch.exclude]}


def plan_workspace(batch: BatchFile, remote: bool) -> Workspace:
    base = batch.path.parent
    root = (base / batch.workspace).resolve() if batch.workspace else base.resolve()
    if not root.is_dir():
        raise ParseError(f"workspace: '{batch.workspace}' is no folder",
                         batch.places.get("workspace"))
    if not remote:
        return Workspace(root, "local")
    return Workspace(root, "shared" if batch.shared_workspace else "upload")
