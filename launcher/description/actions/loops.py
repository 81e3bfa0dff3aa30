"""Loops: `for` (N copies, `$(index NAME)`) and `for_each` (`$(for-var NAME)`).

A loop runs at most MAX_ITERATIONS times: a launch file's typo (`len: 100000000`) is an error
that says so, not a launcher that fills memory.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

from launcher.description.action import Action, PopLocals, PushLocals
from launcher.description.fields import Kind, attr, resolve
from launcher.description.registry import action
from launcher.description.substitution import perform_text, to_text
from launcher.description.substitutions.configuration import loop_key
from launcher.errors import ExecutionError
from launcher.records import dataclass, field
from launcher.runtime.context import LaunchContext

MAX_ITERATIONS = 10_000


def _check_count(tag: str, count: int) -> None:
    if count > MAX_ITERATIONS:
        raise ExecutionError(f"{tag}: {count:,} iterations is past the limit of "
                             f"{MAX_ITERATIONS:,}")


def _iteration(values: dict[str, Any], body: Sequence[Action]) -> list[Action]:
    return [PushLocals(values={loop_key(k): str(v) for k, v in values.items()}), *body,
            PopLocals()]


@action("for")
@dataclass(kw_only=True, eq=False)
class ForLoop(Action):
    length: Any = attr(Kind.INT, name="len", required=True, minimum=0,
                       doc="How many times (a whole number ≥ 0).")
    name: str = attr(Kind.NAME, required=True, doc="The index name, for $(index NAME).")
    actions: list[Action] = attr(Kind.CHILDREN, doc="The body, repeated.")
    function: Callable[[int], Sequence[Action] | None] | None = field(default=None, repr=False)

    def execute(self, context: LaunchContext) -> list[Action]:
        spec = type(self).__dataclass_fields__["length"].metadata["launch"]
        count = resolve(context, self.length, Kind.INT, "len", spec)
        _check_count("for", count)
        out: list[Action] = []
        for i in range(count):
            body = list(self.function(i) or []) if self.function else self.actions
            out += _iteration({self.name: i}, body)
        return out

    def sub_actions(self) -> Sequence[Action]:
        return self.actions


@action("for_each")
@dataclass(kw_only=True, eq=False)
class ForEach(Action):
    """`values` is `;`-separated YAML maps: `{name: a, x: 1};{name: b, x: 2}`."""

    input_values: Any = attr(Kind.TEXT, name="values", required=True,
                             doc="';'-separated YAML maps, one per iteration.")
    actions: list[Action] = attr(Kind.CHILDREN, doc="The body, once per map.")
    function: Callable[..., Sequence[Action] | None] | None = field(default=None, repr=False)

    def execute(self, context: LaunchContext) -> list[Action]:
        import yaml  # only when a for_each runs: a launch's start (and --show-args) needs none

        text = perform_text(context, to_text(self.input_values))
        chunks = [c for c in (c.strip() for c in text.split(";")) if c]
        _check_count("for_each", len(chunks))
        out: list[Action] = []
        for number, chunk in enumerate(chunks, 1):
            try:
                values = yaml.safe_load(chunk)
            except yaml.YAMLError as exc:
                raise ExecutionError(f"for_each: set {number} ('{chunk}') is not valid YAML: "
                                     f"{getattr(exc, 'problem', exc)}") from None
            if values is None:
                values = {}
            if not isinstance(values, dict):
                raise ExecutionError(f"for_each: set {number} ('{chunk}') must be a map "
                                     "like {name: a, x: 1}")
            body = list(self.function(**values) or []) if self.function else self.actions
            out += _iteration(values, body)
        return out

    def sub_actions(self) -> Sequence[Action]:
        return self.actions
