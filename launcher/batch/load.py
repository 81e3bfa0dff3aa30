"""A batch file → a BatchFile: composed (not loaded) YAML, so that every error points at its
key or value; every check that needs only the file is made here."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from launcher import records
from launcher.batch.resources import RAY_OWN
from launcher.batch.spec import BatchFile, Entry, Resources
from launcher.errors import Location, ParseError, did_you_mean
from launcher.schema import Kind, build, declared_fields, parse_bytes
from launcher.user_files import check_yaml_depth, read_text

STOP_KEYS = ("duration", "sim_duration", "until")


class _Doc:
    """The composed document of one file, and places in it."""

    def __init__(self, path: Path) -> None:
        import yaml

        self.yaml = yaml
        self.path = path
        self.construct = yaml.SafeLoader("").construct_object

    def at(self, node: Any) -> Location:
        return Location(str(self.path), node.start_mark.line + 1, node.start_mark.column + 1)

    def pairs(self, node: Any, what: str) -> dict[str, tuple[Any, Any]]:
        """key → (key node, value node) of a mapping, refusing duplicates."""
        if not isinstance(node, self.yaml.MappingNode):
            raise ParseError(f"{what or 'the batch file'}: expected a mapping (key: value), got "
                             f"{self.shown(node)}", self.at(node))
        out: dict[str, tuple[Any, Any]] = {}
        for key, value in node.value:
            name = str(key.value)
            if name in out:
                raise ParseError(f"{what}: '{name}' is given twice (first at line "
                                 f"{out[name][0].start_mark.line + 1})", self.at(key))
            out[name] = (key, value)
        return out

    def shown(self, node: Any) -> str:
        if isinstance(node, self.yaml.ScalarNode):
            return repr(node.value) if node.value else "nothing"
        if isinstance(node, self.yaml.SequenceNode):
            return "a list" if node.value else "an empty list"
        return "a mapping"

    def text(self, node: Any, what: str) -> str:
        """A scalar as written (`0.50` stays `0.50`)."""
        if not isinstance(node, self.yaml.ScalarNode) or node.tag.endswith(":null"):
            raise ParseError(f"{what}: expected a value, got {self.shown(node)}", self.at(node))
        return str(node.value)

    def record(self, cls: type, node: Any, what: str
               ) -> tuple[Any, dict[str, Any], dict[str, Location]]:
        """`cls` from a mapping's plain keys; its VALUE keys' nodes are handed back, and
        where each key's value is."""
        structured = {f.name for f, spec in declared_fields(cls) if spec.kind is Kind.VALUE}
        plain, nested, places = {}, {}, {}
        for name, (key, value) in self.pairs(node, what).items():
            places[name] = (self.at(key), self.at(value))
            if name in structured:
                nested[name] = value
            else:
                plain[name] = self.construct(value, deep=True)
        made = build(cls, plain, what, places=places, at=self.at(node))
        return made, nested, {k: v for k, (_, v) in places.items()}


def load_batch(path: Path) -> BatchFile:
    """The batch file at `path`, checked."""
    doc = _Doc(path)
    if not path.is_file():
        raise ParseError(f"batch file '{path}' does not exist"
                         f"{' (it is a folder)' if path.is_dir() else ''}")
    try:
        text = read_text(path)
    except UnicodeDecodeError:
        raise ParseError(f"{path}: not UTF-8 text") from None
    except OSError as exc:
        raise ParseError(f"{path}: cannot be read: {exc.strerror}") from None
    check_yaml_depth(text, str(path))
    try:
        root = doc.yaml.compose(text, Loader=doc.yaml.SafeLoader)
    except doc.yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        where = Location(str(path), mark.line + 1, mark.column + 1) if mark else None
        raise ParseError(f"not valid YAML: {getattr(exc, 'problem', None) or exc}",
                         where) from None
    if root is None:
        raise ParseError("the batch file is empty; expected at least `jobs:` with a test "
                         "or a launch file", Location(str(path)))
    batch, nested, places = doc.record(BatchFile, root, "")
    if "jobs" not in nested:
        raise ParseError("no `jobs:`; expected a list of jobs (- test: FILE or - launch: "
                         "FILE)", doc.at(root))
    batch = records.replace(batch, path=path, places=places,
                            **_nested(doc, nested, places))
    jobs = _jobs(doc, nested["jobs"], batch)
    return records.replace(batch, jobs=jobs)


def _nested(doc: _Doc, nested: dict[str, Any], places: dict[str, Location]
            ) -> dict[str, Any]:
    out: dict[str, Any] = {}
    if "matrix" in nested:
        out["matrix"] = _matrix(doc, nested["matrix"], "matrix", places)
    out["seeds"] = _seeds(doc, nested["seeds"]) if "seeds" in nested else [0]
    if "resources" in nested:
        out["resources"] = parse_resources(doc, nested["resources"], "resources")
    else:
        out["resources"] = parse_resources(doc, None, "resources")
    if "env" in nested:
        out["env"] = _strings(doc, nested["env"], "env")
    return out


def _matrix(doc: _Doc, node: Any, what: str,
            places: dict[str, Location]) -> dict[str, list[str]]:
    """The matrix; each key's place goes into `places` as `matrix.KEY`."""
    pairs = doc.pairs(node, what)
    if not pairs:
        raise ParseError(f"{what}: empty; give each key a list of values (world_name: "
                         "[empty.sdf, world.sdf]), or leave matrix out to run each job once",
                         doc.at(node))
    matrix = {}
    for name, (key, value) in pairs.items():
        if name == "seed":
            raise ParseError(f"{what}: 'seed' is the batch's own: use seeds: [0, 1, 2]",
                             doc.at(key))
        items = value.value if isinstance(value, doc.yaml.SequenceNode) else [value]
        if not items:
            raise ParseError(f"{what}: '{name}' has no values; give it at least one",
                             doc.at(value))
        values = [doc.text(item, f"{what}.{name}") for item in items]
        matrix[name] = list(dict.fromkeys(values))
        places[f"matrix.{name}"] = doc.at(key)
    return matrix


def _seeds(doc: _Doc, node: Any) -> list[int]:
    expected = "expected a whole number ≥ 1 (10: seeds 0-9) or a list of whole numbers ≥ 0"
    value = doc.construct(node, deep=True)
    if isinstance(value, int) and not isinstance(value, bool) and value >= 1:
        return list(range(value))
    if isinstance(value, list) and value and all(
            isinstance(v, int) and not isinstance(v, bool) and v >= 0 for v in value):
        return list(dict.fromkeys(value))
    raise ParseError(f"seeds: {expected}, got {value!r}", doc.at(node))


GRAPH_OWN = ("LAUNCHER_RUN_DIR", "LAUNCHER_ROUTER", "LAUNCHER_LOG_DIR", "ROS_LOG_DIR")


def _strings(doc: _Doc, node: Any, what: str) -> dict[str, str]:
    out = {}
    for name, (key, value) in doc.pairs(node, what).items():
        if what.endswith("env") and name in GRAPH_OWN:
            raise ParseError(f"{what}: {name} is each job's own (its graph and its logs, "
                             "which come back with its results)", doc.at(key))
        text = doc.text(value, f"{what}.{name}")
        out[name] = text.lower() if value.tag.endswith(":bool") else text
    return out


def parse_resources(doc: _Doc, node: Any, what: str) -> Resources:
    """Resources from a mapping node of a batch file (None: the defaults)."""
    if node is None:
        return Resources()
    made, nested, places = doc.record(Resources, node, what)
    if made.memory is not None:
        try:
            parse_bytes(made.memory, f"{what}.memory")
        except ParseError as exc:
            raise exc.at(places.get("memory")) from None
    custom = {}
    if "custom" in nested:
        for name, (key, value) in doc.pairs(nested["custom"], f"{what}.custom").items():
            if name in RAY_OWN or name.startswith("node:"):
                raise ParseError(f"{what}.custom: '{name}' is Ray's own; say cpus, gpus or "
                                 "memory, or name a resource of your nodes", doc.at(key))
            amount = doc.construct(value)
            if isinstance(amount, bool) or not isinstance(amount, int | float) or amount <= 0:
                raise ParseError(f"{what}.custom.{name}: expected a number > 0, got "
                                 f"{amount!r}", doc.at(value))
            custom[name] = float(amount)
    return records.replace(made, custom=custom)


def _jobs(doc: _Doc, node: Any, batch: BatchFile) -> list[Entry]:
    if not isinstance(node, doc.yaml.SequenceNode) or not node.value:
        raise ParseError("jobs: expected a list of jobs (- test: FILE or - launch: FILE), "
                         f"got {doc.shown(node)}", doc.at(node))
    return [_entry(doc, item, batch, n) for n, item in enumerate(node.value, 1)]


def _entry(doc: _Doc, node: Any, batch: BatchFile, number: int) -> Entry:
    what = f"jobs[{number}]"
    entry, nested, places = doc.record(Entry, node, what)
    entry = records.replace(entry, where=doc.at(node), places=places)
    extra: dict[str, Any] = {}
    if "arguments" in nested:
        extra["arguments"] = _strings(doc, nested["arguments"], f"{what}.arguments")
        places.update({f"arguments.{k}": doc.at(key) for k, (key, _) in
                       doc.pairs(nested["arguments"], what).items()})
        if "seed" in extra["arguments"]:
            raise ParseError(f"{what}.arguments: 'seed' is the batch's own: use seeds:",
                             doc.at(nested["arguments"]))
    if "matrix" in nested:
        extra["matrix"] = _matrix(doc, nested["matrix"], f"{what}.matrix", places)
    if "resources" in nested:
        extra["resources"] = parse_resources(doc, nested["resources"], f"{what}.resources")
    if "env" in nested:
        extra["env"] = _strings(doc, nested["env"], f"{what}.env")
    entry = records.replace(entry, **extra)
    _check_kind(entry, what, batch)
    _check_file(entry, what, batch)
    return entry


def _check_kind(entry: Entry, what: str, batch: BatchFile) -> None:
    if (entry.test is None) == (entry.launch is None):
        raise ParseError(f"{what}: give one of test: FILE (a launch test) or launch: FILE "
                         "(a launch file)", entry.where)
    given = [k for k in STOP_KEYS if getattr(entry, k) is not None]
    place = entry.places.get(given[0]) if given else entry.where
    if entry.kind == "test" and given:
        raise ParseError(f"{what}: {given[0]} is for launch jobs; a test ends itself "
                         "(timeout bounds it)", place)
    if entry.kind == "launch" and not given:
        raise ParseError(f"{what}: launch: {entry.launch} needs one of duration, "
                         "sim_duration or until", entry.where)
    if len(given) > 1:
        raise ParseError(f"{what}: {given[0]} and {given[1]} both given; say one",
                         entry.places.get(given[1]))
    lockstep = entry.lockstep if entry.lockstep is not None else batch.lockstep
    if entry.duration is not None and lockstep:
        raise ParseError(f"{what}: duration is wall time, which a lockstep run does not "
                         f"repeat; use sim_duration: {entry.duration:g}", place)
    timeout = entry.timeout if entry.timeout is not None else batch.timeout
    if entry.duration is not None and timeout <= entry.duration:
        raise ParseError(f"{what}: timeout {timeout:g} is not longer than duration "
                         f"{entry.duration:g}", entry.places.get("timeout", place))


def _check_file(entry: Entry, what: str, batch: BatchFile) -> None:
    if entry.package:  # found through the package index, by the inspector
        return
    key = entry.kind
    file = batch.path.parent / entry.file
    if file.is_file():
        return
    head = entry.file.rpartition("/")[0]  # the folder as written: candidates keep it
    beside = [f"{head}/{p.name}" if head else p.name for p in file.parent.glob("*")
              if p.is_file()] if file.parent.is_dir() else []
    raise ParseError(f"{key}: '{entry.file}' does not exist"
                     f"{did_you_mean(entry.file, beside)}", entry.places.get(key))
