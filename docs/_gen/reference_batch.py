"""The batch file's reference (`launcher batch`): every key, from the fields declared once in
launcher/batch/spec.py."""

from __future__ import annotations

from md_tables import code, table

from launcher import records
from launcher.batch.spec import BatchFile, Entry, Resources
from launcher.schema import Kind, declared_fields, frontend_name

TITLE = """# The batch file

Generated from the declared fields at each build. A batch file is YAML; paths in it are
relative to it. A key that is not listed here is refused at its line (with "did you mean"), and
so is a value of the wrong kind. [Many scenarios at once](../guides/batch.md) shows it in use.
"""

KINDS = {Kind.FLOAT: "number", Kind.INT: "whole number", Kind.BOOL: "true/false",
         Kind.TEXT: "text", Kind.NAME: "name", Kind.NAMES: "list of texts"}
NESTED = {"jobs": "list of jobs", "matrix": "NAME: [values]", "seeds": "count or list",
          "resources": "mapping", "env": "NAME: value", "arguments": "NAME: value",
          "custom": "NAME: amount"}


def _rows(cls: type) -> list[tuple[str, str, str, str]]:
    rows = []
    for f, spec in declared_fields(cls):
        name = frontend_name(f, spec)
        kind = NESTED.get(name, KINDS.get(spec.kind, "value"))
        default = "" if f.default in (None, records.MISSING) else f.default
        shown = str(default).lower() if isinstance(default, bool) else f"{default:g}" \
            if isinstance(default, float) else str(default)
        rows.append((code(name), kind, code(shown) if shown else "", spec.doc))
    return rows


def page() -> str:
    header = ("key", "kind", "default", "what it says")
    return "\n".join([
        TITLE, "## The batch\n", table(header, _rows(BatchFile)),
        "## A job (an item of `jobs`)\n",
        "Each item names its file with `test:` or `launch:`; a launch job also says how it "
        "ends: `duration`, `sim_duration` or `until`. Its other keys, where given, win over the "
        "batch's.\n", table(header, _rows(Entry)),
        "## Resources (`resources`, of the batch or of a job)\n", table(header,
                                                                         _rows(Resources))])
