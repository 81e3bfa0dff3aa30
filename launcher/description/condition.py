"""`if` / `unless` on any tag: the text must be true, false, 1 or 0 (any case)."""

from __future__ import annotations

from launcher.description.substitution import Text_, describe_text, perform_text, to_text
from launcher.errors import Location, SubstitutionError
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext


def evaluate_condition_text(text: str, what: str = "condition") -> bool:
    low = text.strip().lower()
    if low in ("true", "1"):
        return True
    if low in ("false", "0"):
        return False
    raise SubstitutionError(f"{what}: expected true, false, 1 or 0, got '{text}'")


@dataclass(frozen=True)
class Condition:
    text: Text_
    negate: bool = False
    where: Location | None = None

    def evaluate(self, context: LaunchContext) -> bool:
        what = "unless" if self.negate else "if"
        try:
            value = evaluate_condition_text(perform_text(context, self.text), what)
        except SubstitutionError as exc:
            raise exc.at(self.where) from None
        return value != self.negate

    def describe(self) -> str:
        return f"{'unless' if self.negate else 'if'}={describe_text(self.text)}"


def IfCondition(value: object) -> Condition:  # noqa: N802 - ROS 2 Python API name
    return Condition(to_text(value))


def UnlessCondition(value: object) -> Condition:  # noqa: N802 - ROS 2 Python API name
    return Condition(to_text(value), negate=True)


def entry_applies(context: LaunchContext, entry: object) -> bool:
    """Whether a node's entry (env, remap, param; a composable node) holds: roslaunch takes
    if= and unless= on a node's children too, launch_ros on a composable node (`only_if`,
    `only_unless`)."""
    for field, negate in (("only_if", False), ("only_unless", True)):
        text = getattr(entry, field, None)
        if text is not None and not Condition(text, negate).evaluate(context):
            return False
    return True
