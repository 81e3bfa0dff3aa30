"""A batch as JUnit XML: one test case per job, for a CI's test report."""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from collections import deque
from pathlib import Path

from launcher.batch.matrix import JobPlan
from launcher.batch.results import JobResult, Status

OUTPUT_LINES = 200  # the end of a job's output in <system-out>
# colours, then what XML 1.0 cannot hold (a job's output may have either)
_ESCAPES = re.compile(r"\x1b\[[0-?]*[ -/]*[@-~]")
_NOT_XML = re.compile("[^\t\n\r\x20-\ud7ff\ue000-\ufffd\U00010000-\U0010ffff]")
_KIND = {Status.FAIL: "failure", Status.ERROR: "error", Status.TIMEOUT: "error"}


def write_junit(path: Path, name: str, plans: list[JobPlan], results: dict[str, JobResult],
                logs: Path | None = None) -> None:
    """`logs`: the run's folder, where each result's `log` folder holds its output.log."""
    cases = [_case(name, plan, results.get(plan.id), logs) for plan in plans]
    kinds = [child.tag for case in cases for child in case if child.tag != "properties"]
    wall = sum(r.wall_s for p in plans if (r := results.get(p.id)) is not None)
    suite = ET.Element("testsuite", name=name, tests=str(len(plans)),
                       failures=str(kinds.count("failure")), errors=str(kinds.count("error")),
                       skipped=str(kinds.count("skipped")), time=f"{wall:.3f}")
    suite.extend(cases)
    root = ET.Element("testsuites")
    root.append(suite)
    ET.indent(root)
    path.parent.mkdir(parents=True, exist_ok=True)
    ET.ElementTree(root).write(path, encoding="utf-8", xml_declaration=True)


def _case(suite: str, plan: JobPlan, result: JobResult | None, logs: Path | None) -> ET.Element:
    case = ET.Element("testcase", classname=f"{suite}.{plan.label}",
                      name=plan.title[len(plan.label):],
                      time=f"{result.wall_s:.3f}" if result else "0.000")
    properties = ET.SubElement(case, "properties")
    for key, value in _properties(plan, result).items():
        ET.SubElement(properties, "property", name=key, value=_clean(value))
    if result is None:
        ET.SubElement(case, "skipped", message="not run")
        return case
    if result.status is Status.CANCELLED:
        ET.SubElement(case, "skipped", message="cancelled")
    elif kind := _KIND.get(result.status):
        said = ET.SubElement(case, kind, message=_clean(result.reason or result.status.value))
        said.text = _clean(_details(result))
    if logs is not None and result.log and (output := logs / result.log / "output.log").is_file():
        ET.SubElement(case, "system-out").text = _clean(_tail(output))
    return case


def _properties(plan: JobPlan, result: JobResult | None) -> dict[str, str]:
    found = {**plan.arguments, "seed": str(plan.seed), "repeat": str(plan.repeat)}
    if result is not None:
        known = {"node": result.node, "sim_s": result.sim_s, "rtf": result.rtf,
                 "state": result.state}
        found.update({k: str(v) for k, v in known.items() if v not in (None, "")})
    return found


def _details(result: JobResult) -> str:
    """The reason, then each case that did not pass."""
    lines = [result.reason] + [f"{c.get('name')}: {c.get('status')}: {c.get('message', '')}"
                               for c in result.cases if c.get("status") not in ("pass", "passed")]
    return "\n".join(line for line in lines if line)


def _tail(path: Path) -> str:
    with path.open(encoding="utf-8", errors="replace") as lines:
        return "".join(deque(lines, maxlen=OUTPUT_LINES))


def _clean(text: str) -> str:
    return _NOT_XML.sub("", _ESCAPES.sub("", text))
