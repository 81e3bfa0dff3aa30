"""Hold launcher's shims to the recorded surface of the real packages (surface/*.json).

`python -m tests.fidelity.surface_check` imports every recorded module through launcher's
shims (launcher.compat, as a launch file or node finds them) and prints what differs: modules
that do not import, names that are not there, signatures that refuse a call the real one
takes. `--write-gaps` writes that list to surface/gaps.json, which test_surface.py holds to
the truth both ways (a gap that closes must leave the list). What launcher leaves out on
purpose is in left_out.py, with its reason, and is not a gap.
"""

from __future__ import annotations

import argparse
import importlib
import inspect
import json
import sys
import warnings
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
SURFACE = HERE / "surface"
GAPS = SURFACE / "gaps.json"
RECORD_FILES = ("launch", "launch_xml", "launch_yaml", "launch_ros", "launch_testing",
                "launch_testing_ros", "launch_pytest", "ament_index_python", "rclpy",
                "rcl_interfaces", "lifecycle_msgs", "rospy", "actionlib", "rostest", "roslaunch",
                "rosbag")
POSITIONAL = ("POSITIONAL_ONLY", "POSITIONAL_OR_KEYWORD")


def record() -> dict[str, dict[str, Any]]:
    """Every recorded module of every root: {module: {"names": {...}} or {"error": ...}}."""
    out: dict[str, dict[str, Any]] = {}
    for root in RECORD_FILES:
        out.update(json.loads((SURFACE / f"{root}.json").read_text()))
    newer = SURFACE / "newer.json"
    if newer.exists():
        for module, names in json.loads(newer.read_text()).items():
            out.setdefault(module, {"names": {}})["names"].update(names)
    return out


def ours(thing: Any) -> list[list[Any]] | None:
    try:
        signature = inspect.signature(thing)
    except (TypeError, ValueError):
        return None
    return [[p.name, p.kind.name, None if p.default is p.empty else repr(p.default)]
            for p in signature.parameters.values()]


def refusal(real: list[list[Any]] | None, mine: list[list[Any]] | None,
            method: bool = False) -> str | None:
    """Why a call the real signature takes would fail on ours (None: every such call is
    taken). `method`: both start with self or cls, which are left out."""
    if real is None or mine is None:
        return None
    if method:
        real, mine = real[1:], mine[1:]
    var_pos = any(kind == "VAR_POSITIONAL" for _, kind, _ in mine)
    var_kw = any(kind == "VAR_KEYWORD" for _, kind, _ in mine)
    by_name = {name: (index, kind, default) for index, (name, kind, default) in
               enumerate(mine)}
    for index, (name, kind, _) in enumerate(real):
        if kind == "VAR_POSITIONAL" and not var_pos:
            return "takes no *args"
        if kind == "VAR_KEYWORD" and not var_kw:
            return "takes no **kwargs"
        if kind in POSITIONAL:
            here = mine[index] if index < len(mine) else None
            positional = here is not None and here[1] in POSITIONAL or \
                (here is None or here[1] == "VAR_POSITIONAL") and var_pos
            if not positional:
                return f"argument {index + 1} ({name}) is not taken by position"
        if kind in ("POSITIONAL_OR_KEYWORD", "KEYWORD_ONLY"):
            mine_kind = by_name.get(name, (0, None, None))[1]
            if mine_kind not in ("POSITIONAL_OR_KEYWORD", "KEYWORD_ONLY") and not var_kw:
                return f"no keyword argument {name}"
    optional = {name for name, _, default in real if default is not None} | \
        {name for name, kind, _ in real if kind.startswith("VAR_")}
    real_names = {name for name, _, _ in real}
    for name, kind, default in mine:
        if default is None and not kind.startswith("VAR_") and \
                (name not in real_names or name in optional):
            return f"requires {name}, which the real one does not"
    return None


def check() -> dict[str, list[str]]:
    """The differences: "module", "module:Name" (absent) and "module:Name(…)" (a signature
    that refuses a real call), each with what is wrong."""
    warnings.simplefilter("ignore")
    from launcher import compat
    from tests.fidelity.left_out import LEFT_OUT

    compat.enable_in_process()
    gaps: dict[str, str] = {}
    for dotted, entry in sorted(record().items()):
        if "error" in entry:
            continue  # not importable in the real install either
        try:
            module = importlib.import_module(dotted)
        except Exception as exc:  # noqa: BLE001 (the gap is recorded)
            gaps[dotted] = f"does not import: {type(exc).__name__}: {exc}"[:200]
            continue
        for name, real in sorted(entry["names"].items()):
            key = f"{dotted}:{name}"
            try:
                thing = getattr(module, name)
            except Exception:  # noqa: BLE001 (absent, however it says so)
                gaps[key] = "absent"
                continue
            why = refusal(real.get("signature"), ours(thing)) \
                if real["kind"] in ("class", "function") else None
            if why:
                gaps[key] = f"signature: {why}"
    return {key: why for key, why in sorted(gaps.items()) if key not in LEFT_OUT}


def missing(key: str) -> bool:
    """Whether "module" or "module:Name" is missing under launcher's shims (run in a process
    where launcher.compat is enabled)."""
    module, _, name = key.partition(":")
    try:
        found = importlib.import_module(module)
    except Exception:  # noqa: BLE001
        return True
    return bool(name) and not hasattr(found, name)


ROS1 = ("rospy", "actionlib", "rostest", "roslaunch", "rosbag")


def family(key: str) -> str:
    return "ROS 1" if key.partition(".")[0].partition(":")[0] in ROS1 else "ROS 2"


def sizes() -> dict[str, dict[str, int]]:
    """Per family (ROS 2, ROS 1): the recorded surface (modules and names importable in the
    real install), and how much of it is left out on purpose (a module left out counts with
    its names)."""
    from tests.fidelity.left_out import LEFT_OUT

    everything = record()
    out = {name: {"modules": 0, "names": 0, "left_out": 0} for name in ("ROS 2", "ROS 1")}
    for dotted, entry in everything.items():
        if "error" not in entry:
            out[family(dotted)]["modules"] += 1
            out[family(dotted)]["names"] += len(entry["names"])
    for key in LEFT_OUT:
        module, _, name = key.partition(":")
        covered = 1 if name else 1 + len(everything.get(module, {}).get("names", {}))
        out[family(key)]["left_out"] += covered
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--write-gaps", action="store_true")
    parser.add_argument("--left-out", action="store_true",
                        help="print the left-out entries that are no longer missing")
    options = parser.parse_args()
    if options.left_out:
        from launcher import compat
        from tests.fidelity.left_out import LEFT_OUT

        compat.enable_in_process()
        json.dump([key for key in LEFT_OUT if not missing(key)], sys.stdout)
        return
    gaps = check()
    if options.write_gaps:
        GAPS.write_text(json.dumps(gaps, indent=1) + "\n")
    json.dump(gaps, sys.stdout, indent=1)


if __name__ == "__main__":
    main()
