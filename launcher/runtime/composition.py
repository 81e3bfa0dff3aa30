"""Loading composable nodes into component containers: what the launch asks and who asks.

`node_container` and `load_composable_node` (description/actions/composition.py) make one
LoadRequest per composable node; the launch service hands them to its Loader, which asks the
container (its `_container/load_node` service, over the bus) one at a time, in order, and says
how each went from its own thread. The runtime itself imports no bus: `launcher launch` gives
the service a Loader (cli/components.py).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, Protocol

from launcher.records import dataclass, field


@dataclass
class LoadRequest:
    package: str
    plugin: str
    node_name: str = ""  # empty: the component's own
    namespace: str = ""
    remaps: list[tuple[str, str]] = field(default_factory=list)
    parameters: dict[str, Any] = field(default_factory=dict)  # typed values
    param_files: list[str] = field(default_factory=list)  # read by the loader, in order
    extra_arguments: dict[str, Any] = field(default_factory=dict)
    where: Any = None  # the composable_node's place in its launch file

    @property
    def label(self) -> str:
        if not self.node_name:
            return self.plugin
        space = self.namespace.rstrip("/")
        return f"{space}/{self.node_name}" if space.startswith("/") or not space \
            else f"/{space}/{self.node_name}"


# done(request, full node name, error): from the loader's thread; error "" when it loaded
Done = Callable[[LoadRequest, str, str], None]


class Loader(Protocol):
    def load(self, container: str, requests: list[LoadRequest], environment: dict[str, str],
             alive: Callable[[], bool] | None, done: Done) -> None:
        """Ask `container` (a fully qualified node name) to load `requests`, in order. `alive`
        says whether the container this launch started still runs (None: not this launch's);
        a container that is gone, or never answers, fails every request it was given."""

    def cancel(self) -> None:
        """The launch is ending: give up waiting (requests not sent are dropped)."""

    def close(self) -> None:
        """Leave the bus; the launch has ended."""
