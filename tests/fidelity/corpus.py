"""The differential corpus: launch files generated per tag, attribute, substitution and
nesting, each run through the real tool (recorded under expected/) and through launcher.

A case is a small launch file (and the files it includes or reads) with the corpus's probe
node (`probe`, tests/fidelity/workspace) standing where a user's node would. The probe records
how it was started; the comparison is of those records and of the exit status. Case names are
stable: a recording is found by name, and a case whose text changed is recorded again.
"""

from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass, field

from tests.fidelity import cases_python, cases_ros1, cases_ros2


@dataclass(frozen=True)
class Case:
    name: str  # "ros1/param/value-int": the flavour, then a family, then the variation
    files: dict[str, str]  # relative path → text; `main` among them
    main: str = "main.launch"
    args: tuple[str, ...] = ()  # name:=value on the command line
    env: dict[str, str] = field(default_factory=dict)  # the user's shell adds these
    stop_after: float | None = None  # end a launch that would run on (respawn) after this

    @property
    def script(self) -> bool:
        """A script of launch's Python API (a LaunchService run by hand), run with python."""
        return self.main.endswith(".py") and not self.main.endswith("launch.py")

    @property
    def flavour(self) -> str:
        return self.name.split("/", 1)[0]

    @property
    def digest(self) -> str:
        """What the recording was made of: a changed case is recorded again."""
        text = json.dumps([self.files, self.main, self.args, self.env, self.stop_after],
                          sort_keys=True)
        return hashlib.sha256(text.encode()).hexdigest()[:16]


def cases() -> list[Case]:
    found = [Case(**spec) for spec in [*cases_ros1.specs(), *cases_ros2.specs(),
                                        *cases_python.specs()]]
    names = [case.name for case in found]
    duplicates = {name for name in names if names.count(name) > 1}
    assert not duplicates, f"corpus case names used twice: {sorted(duplicates)}"
    return found
