"""The base of the substitutions that look a NAME up, with an optional DEFAULT: `$(var)`,
`$(for-var)`, `$(env)`, `$(param)`."""

from __future__ import annotations

from collections.abc import Mapping

from launcher.description.substitution import Substitution, Text_, perform_text
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext


@dataclass(frozen=True)
class Lookup(Substitution):
    """NAME's value among `_values(context)`; else DEFAULT when one is given; else an error
    that says what `_unset` says."""

    name: Text_
    default: Text_ | None = None

    def perform(self, context: LaunchContext) -> str:
        name = perform_text(context, self.name)
        values = self._values(context)
        if name in values:
            return values[name]
        if self.default is not None:
            return perform_text(context, self.default)
        raise self.fail(self._unset(name, values))

    def _values(self, context: LaunchContext) -> Mapping[str, str]:
        raise NotImplementedError

    def _unset(self, name: str, values: Mapping[str, str]) -> str:
        """Why NAME has no value, and how to give it one."""
        raise NotImplementedError
