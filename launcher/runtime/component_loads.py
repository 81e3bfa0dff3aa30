"""Composable nodes a launch asks containers to load: each answer is logged, a failure
reported (the launch goes on, its exit status becomes 1); the launch does not end while one is
out. What each container was asked to load is kept, and asked again when the user starts that
container anew (`launcher restart`): its nodes went with its process."""

from __future__ import annotations

from collections.abc import Callable

from launcher.errors import ExecutionError, LaunchError
from launcher.runtime.composition import Loader, LoadRequest
from launcher.runtime.loop import EventLoop


class ComponentLoads:
    def __init__(self, loop: EventLoop, loader: Loader | None,
                 log: Callable[[str, str, str], None], report: Callable[[LaunchError], None],
                 answered: Callable[[], None]) -> None:
        self.loop, self.loader, self.log, self.report = loop, loader, log, report
        self.answered = answered
        self.out = 0  # asked for and not answered yet
        self.cancelled = False
        self.asked: dict[str, list[tuple[list[LoadRequest], dict[str, str],
                                         Callable[[], bool] | None]]] = {}

    def load(self, container: str, requests: list[LoadRequest], environment: dict[str, str],
             alive: Callable[[], bool] | None) -> None:
        """Ask `container` to load `requests` (its answers come on a loader's thread)."""
        if self.loader is None:
            raise ExecutionError("composable nodes need the bus, which this run lacks "
                                 "(run it with `launcher launch`)")
        if not requests or self.cancelled:
            return
        self.asked.setdefault(container, []).append((requests, environment, alive))
        self._send(container, requests, environment, alive)

    def reload(self, container: str) -> None:
        """Ask `container` again for every node it was asked to load (it started anew)."""
        for requests, environment, alive in self.asked.get(container, []):
            if not self.cancelled:
                self._send(container, requests, environment, alive)

    def _send(self, container: str, requests: list[LoadRequest], environment: dict[str, str],
              alive: Callable[[], bool] | None) -> None:
        assert self.loader is not None
        self.loop.open_posting()
        self.out += len(requests)

        def done(request: LoadRequest, name: str, error: str) -> None:  # a loader's thread
            self.loop.call_soon_threadsafe(self._on_loaded, container, request, name, error)

        self.loader.load(container, requests, environment, alive, done)

    def _on_loaded(self, container: str, request: LoadRequest, name: str, error: str) -> None:
        self.out = max(0, self.out - 1)
        if error and not self.cancelled:
            self.report(ExecutionError(f"composable node '{request.label}' "
                                       f"({request.plugin}) was not loaded into "
                                       f"'{container}': {error}", request.where))
        elif not error:
            self.log("INFO", "launch", f"Loaded node '{name}' in container '{container}'")
        self.answered()

    def cancel(self) -> None:
        self.cancelled = True
        if self.loader is not None:
            self.loader.cancel()
        self.out = 0

    def close(self) -> None:
        if self.loader is not None:
            self.loader.close()
