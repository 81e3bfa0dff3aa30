"""The jobs of a batch: each entry × its matrix's combinations × seeds × repeats, and the
selections of the command line (`--only`, `--rerun-failed`)."""

from __future__ import annotations

import hashlib
import itertools
import json
from collections.abc import Iterable, Mapping

from launcher import records
from launcher.batch.spec import BatchFile, Entry
from launcher.errors import UsageError, did_you_mean

MOST_JOBS = 100_000


@records.dataclass(frozen=True)
class Overrides:
    """The command line's: `NAME:=VALUE` fixes NAME for every job; `--matrix NAME=VALUE`
    adds a key or replaces its values."""

    fixed: dict[str, str] = records.field(default_factory=dict)
    matrix: dict[str, list[str]] = records.field(default_factory=dict)


@records.dataclass(frozen=True)
class JobPlan:
    id: str  # stable across runs of an unchanged entry
    label: str  # the entry's name
    number: int  # the entry's index in `jobs:`
    entry: Entry
    arguments: dict[str, str]  # every launch argument the job is given
    varied: dict[str, str]  # those of them from the matrix
    seed: int
    repeat: int

    @property
    def title(self) -> str:
        """`drive[world=a.sdf, seed=3]`"""
        parts = [f"{k}={v}" for k, v in self.varied.items()] + [f"seed={self.seed}"]
        if self.repeat:
            parts.append(f"repeat={self.repeat}")
        return f"{self.label}[{', '.join(parts)}]"


def entry_matrix(batch: BatchFile, entry: Entry, overrides: Overrides) -> dict[str, list[str]]:
    """The matrix one entry runs over, keys in the order written."""
    matrix = {**batch.matrix, **entry.matrix, **overrides.matrix}
    return {k: v for k, v in matrix.items() if k not in overrides.fixed}


def label_of(entry: Entry) -> str:
    return entry.name or entry.file.rsplit("/", 1)[-1].split(".")[0]


def job_id(entry: Entry, number: int, arguments: Mapping[str, str], seed: int,
           repeat: int) -> str:
    """Stable while the entry and its place stay: two entries of one file differ."""
    what = {"number": number, "kind": entry.kind, "file": entry.file,
            "package": entry.package, "name": entry.name, "lockstep": entry.lockstep,
            "env": entry.env, "stop": records.asdict(entry.stop),
            "arguments": dict(sorted(arguments.items())), "seed": seed, "repeat": repeat}
    return hashlib.sha1(json.dumps(what, sort_keys=True).encode()).hexdigest()[:10]


def expand(batch: BatchFile, overrides: Overrides) -> list[JobPlan]:
    """Every job, repeats outermost and combinations innermost (the table fills evenly while
    a batch runs)."""
    per_entry = []
    for number, entry in enumerate(batch.jobs):
        matrix = entry_matrix(batch, entry, overrides)
        combos = [dict(zip(matrix, values, strict=True))
                  for values in itertools.product(*matrix.values())]
        per_entry.append((number, entry, combos))
    total = sum(len(c) for _, _, c in per_entry) * len(batch.seeds) * batch.repeats
    if total > 10 * MOST_JOBS:
        raise UsageError(f"the batch makes {total:,} jobs; at most {MOST_JOBS:,} are run at "
                         "once: split the matrix")
    plans = []
    for repeat, seed in itertools.product(range(batch.repeats), batch.seeds):
        for number, entry, combos in per_entry:
            for varied in combos:
                arguments = {**entry.arguments, **varied, **overrides.fixed}
                plans.append(JobPlan(job_id(entry, number, arguments, seed, repeat),
                                     label_of(entry),
                                     number, entry, arguments, varied, seed, repeat))
    return plans


def parse_pairs(items: Iterable[str], option: str) -> dict[str, list[str]]:
    """A repeatable `OPTION NAME=VALUE`: each NAME's values, in the order given."""
    pairs: dict[str, list[str]] = {}
    for item in items:
        name, sep, value = item.partition("=")
        if not sep or not name:
            raise UsageError(f"{option} {item}: expected NAME=VALUE (world=empty.sdf)")
        pairs.setdefault(name, []).append(value)
    return pairs


def parse_only(items: Iterable[str]) -> dict[str, set[str]]:
    """`--only NAME=VALUE` …: repeated NAME = any of its values."""
    return {name: set(values) for name, values in parse_pairs(items, "--only").items()}


def _facet(plan: JobPlan, name: str) -> str | None:
    if name == "seed":
        return str(plan.seed)
    if name == "repeat":
        return str(plan.repeat)
    if name == "job":
        return plan.label
    return plan.varied.get(name, plan.arguments.get(name))


def select(plans: list[JobPlan], only: Mapping[str, set[str]],
           rerun: set[str] | None = None) -> list[JobPlan]:
    """The jobs `--only` keeps (every NAME matches one of its values) and, with `rerun`, only
    those ids."""
    for name, values in only.items():
        known = {v for p in plans if (v := _facet(p, name)) is not None}
        if not known:
            keys = sorted({k for p in plans for k in p.varied} | {"seed", "repeat", "job"})
            raise UsageError(f"--only {name}=…: '{name}' is no matrix key"
                             f"{did_you_mean(name, keys)}; the keys: {', '.join(keys)}")
        for value in values - known:
            raise UsageError(f"--only {name}={value}: not a value of {name} "
                             f"({', '.join(sorted(known))})")
    kept = [p for p in plans if all(_facet(p, n) in vs for n, vs in only.items())]
    kept = kept if rerun is None else [p for p in kept if p.id in rerun]
    if len(kept) > MOST_JOBS:
        raise UsageError(f"the batch makes {len(kept):,} jobs; at most {MOST_JOBS:,} are run "
                         "at once: narrow it with --only, or split the matrix")
    return kept
