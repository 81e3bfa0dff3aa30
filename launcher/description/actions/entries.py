"""A name and its value: the entries an include's `arg`, a process's `env`, a group's `keep`
and a composable node's `extra_arg` hold, declared once (each says what its name names)."""

from __future__ import annotations

from launcher.description.fields import Kind, attr
from launcher.description.substitution import Text_
from launcher.records import dataclass


@dataclass(eq=False)
class NameValue:
    name: Text_ = attr(Kind.TEXT, required=True, doc="The name.")
    value: Text_ = attr(Kind.TEXT, required=True, doc="Its value.")
