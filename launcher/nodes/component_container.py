"""component_container: one process that loads components (launch_ros's composition).

The container is a node (default name `ComponentManager`, as rclcpp's) offering
`~/_container/load_node`, `~/_container/unload_node` and `~/_container/list_nodes`
(composition_interfaces). A load finds the plugin in the package's declared components
(launcher/packages/components.py), and calls it in the component's own thread inside a scope
(launcher/bus/components.py) that gives its nodes the requested name, namespace, remaps and
parameters and the container's one Zenoh session.

Isolation: each component's nodes are spun by that component's thread alone, so a callback that
blocks stops only its own component (as rclcpp's component_container_isolated; the `_mt`
and plain names give the same container). A component whose constructor raises is not loaded
and the load answers why; one whose callback raises is unloaded and the container says so on
stderr; one that ends its own spin (a one-shot, like `create`) is unloaded quietly. On SIGINT or
SIGTERM every component is stopped, then the container's node; a component that does not stop
within STOP_WAIT seconds is abandoned (its thread is a daemon) and its entities undeclared.
"""

from __future__ import annotations

import contextlib
import importlib
import itertools
import signal
import sys
import threading
from dataclasses import dataclass, field
from typing import Any

from launcher.bus import components
from launcher.bus.node import Node
from launcher.errors import LaunchError, reported

LOAD, UNLOAD, LIST = ("composition_interfaces/srv/LoadNode",
                      "composition_interfaces/srv/UnloadNode",
                      "composition_interfaces/srv/ListNodes")
CONSTRUCT_WAIT = 60.0  # s a constructor may take before the load is answered as failed
STOP_WAIT = 2.0  # s a component is given to stop
EXTRA_ARGUMENTS = ("use_intra_process_comms", "forward_global_arguments")


@dataclass(eq=False)
class Loaded:
    unique_id: int
    plugin: str
    scope: components.Scope
    made: threading.Event = field(default_factory=threading.Event)
    registered: threading.Event = field(default_factory=threading.Event)
    error: str = ""
    refused: bool = False  # the load was answered as failed: stop once made
    thread: threading.Thread | None = None
    executor: Any = None  # an rclpy executor, for rclpy components

    @property
    def names(self) -> list[str]:
        return [node.fully_qualified_name for node in self.scope.nodes]


class Container:
    def __init__(self, node: Node) -> None:
        self.node = node
        self._index: Any = None
        self._ids = itertools.count(1)
        self._loaded: dict[int, Loaded] = {}
        self._lock = threading.Lock()
        load = node.create_service(LOAD, "~/_container/load_node", self._load_soon)
        load.deferred = True  # (answered from the load's own thread)
        node.create_service(UNLOAD, "~/_container/unload_node", self._unload)
        node.create_service(LIST, "~/_container/list_nodes", self._list)

    # --- services ---------------------------------------------------------------------------
    def _load_soon(self, request: Any, reply: Any) -> None:
        """Each load waits for its component's constructor on a thread of its own: several
        loads are made at once, and the container's node serves on meanwhile."""
        threading.Thread(target=lambda: reply.send(self._load(request, reply.new_response())),
                         name="load", daemon=True).start()

    def _load(self, request: Any, response: Any) -> Any:
        try:
            loaded = self.load(request)
        except LaunchError as exc:
            response.success, response.error_message = False, exc.message
            return response
        response.success = True
        response.full_node_name = loaded.names[0] if loaded.names else ""
        response.unique_id = loaded.unique_id
        return response

    def _unload(self, request: Any, response: Any) -> Any:
        with self._lock:
            loaded = self._loaded.get(int(request.unique_id))
        if loaded is None:
            response.success = False
            response.error_message = f"no node with unique id {request.unique_id} is loaded"
            return response
        self.stop(loaded)
        response.success = True
        return response

    def _list(self, _request: Any, response: Any) -> Any:
        with self._lock:
            rows = [(name, loaded.unique_id) for loaded in self._loaded.values()
                    for name in loaded.names]
        response.full_node_names = [name for name, _ in rows]
        response.unique_ids = [number for _, number in rows]
        return response

    # --- loading ----------------------------------------------------------------------------
    def load(self, request: Any) -> Loaded:
        from launcher.bus.parameters import from_message
        from launcher.packages.components import find_component

        plugin = request.plugin_name
        component = find_component(self.index().get(request.package_name), plugin)
        argv = ["--ros-args"]
        if request.node_name:
            argv += ["-r", f"__node:={request.node_name}"]
        if request.node_namespace:
            argv += ["-r", f"__ns:={request.node_namespace}"]
        for rule in request.remap_rules:
            if ":=" not in rule:
                raise LaunchError(f"remap rule '{rule}': expected FROM:=TO")
            argv += ["-r", rule]
        if request.log_level:
            argv += ["--log-level", _LEVELS.get(int(request.log_level), "INFO")]
        for extra in request.extra_arguments:
            if extra.name not in EXTRA_ARGUMENTS:
                raise LaunchError(f"unknown extra argument '{extra.name}'; the container "
                                  f"knows: {', '.join(EXTRA_ARGUMENTS)}")
        if request.node_name:  # the name is known: refuse a second one before making it
            space = request.node_namespace.strip("/")
            self._check_free(f"/{space}/{request.node_name}" if space
                             else f"/{request.node_name}")
        parameters = {p.name: from_message(p.value) for p in request.parameters}
        scope = components.Scope(argv, parameters, self.node.session)
        loaded = Loaded(next(self._ids), plugin, scope)
        loaded.thread = threading.Thread(target=self._run, args=(loaded, component),
                                         name=f"component-{loaded.unique_id}", daemon=True)
        loaded.thread.start()
        try:
            if not loaded.made.wait(CONSTRUCT_WAIT):
                loaded.refused = True
                raise LaunchError(f"{plugin}: its constructor did not return within "
                                  f"{CONSTRUCT_WAIT:g} s")
            if loaded.error:
                raise LaunchError(f"{plugin}: its constructor raised {loaded.error}")
            if not loaded.names:
                loaded.refused = True
                raise LaunchError(f"{plugin}: it made no node (a component is a callable "
                                  "that makes a launcher or rclpy node)")
            with self._lock:
                try:
                    for name in loaded.names:
                        self._check_free(name)
                except LaunchError:
                    loaded.refused = True  # its thread destroys what it made
                    raise
                self._loaded[loaded.unique_id] = loaded
        finally:
            loaded.registered.set()  # only now may its thread spin (or end, and unlist it)
        self.node.get_logger().info(f"loaded {plugin} as {', '.join(loaded.names)} "
                                    f"(unique id {loaded.unique_id})")
        return loaded

    def _check_free(self, name: str) -> None:
        taken = {n: other for other in list(self._loaded.values()) for n in other.names}
        if name in taken:
            raise LaunchError(f"a node named '{name}' is loaded in this container already "
                              f"(unique id {taken[name].unique_id}); give this one another "
                              "name or namespace")

    def index(self) -> Any:
        with self._lock:  # (loads come at once)
            if self._index is None:
                from launcher.packages.index import PackageIndex

                self._index = PackageIndex.from_environment()
            return self._index

    def _run(self, loaded: Loaded, component: Any) -> None:
        """The component's thread: make it, then spin its nodes until it ends."""
        try:
            if component.folder not in sys.path:
                sys.path.insert(0, component.folder)
            module_name, _, attribute = component.target.partition(":")
            factory: Any = importlib.import_module(module_name)
            for part in attribute.split("."):
                factory = getattr(factory, part)
            if "rclpy" in sys.modules:
                loaded.scope.context = _rclpy_context()
            with components.making(loaded.scope):
                factory()
        except BaseException as exc:  # noqa: BLE001  # the load answers it; the container goes on
            loaded.error = f"{type(exc).__name__}: {exc}"
            _destroy(loaded)
            loaded.made.set()
            return
        loaded.made.set()
        loaded.registered.wait()
        if loaded.refused:  # refused after it was made: too late, or a name taken
            _destroy(loaded)
            return
        try:
            self._spin(loaded)
        except Exception as exc:  # noqa: BLE001  # its callback raised: unload it alone
            self.node.get_logger().error(
                f"{', '.join(loaded.names)} ({loaded.plugin}) raised in a callback: "
                f"{type(exc).__name__}: {exc}; unloaded it, the other nodes keep running")
        finally:
            with self._lock:
                self._loaded.pop(loaded.unique_id, None)
            _destroy(loaded)

    def _spin(self, loaded: Loaded) -> None:
        owners = [node.owner for node in loaded.scope.nodes if node.owner is not None]
        if owners:  # rclpy nodes: their own executor runs their timers and callbacks
            from rclpy.executors import SingleThreadedExecutor

            loaded.executor = SingleThreadedExecutor(context=loaded.scope.context)
            for owner in owners:
                loaded.executor.add_node(owner)
            while loaded.scope.context.ok() and not loaded.refused:
                loaded.executor.spin_once(0.1)
            return
        nodes = loaded.scope.nodes
        while not loaded.refused and not all(n.is_shutdown for n in nodes):
            for node in nodes:
                if not node.is_shutdown:
                    node.spin_once(0.1 / len(nodes))

    def stop(self, loaded: Loaded) -> None:
        loaded.refused = True
        for node in loaded.scope.nodes:
            node.shutdown()
        if loaded.scope.context is not None:
            loaded.scope.context.try_shutdown()
        thread = loaded.thread
        if thread is not None and thread is not threading.current_thread():
            thread.join(STOP_WAIT)
            if thread.is_alive():
                self.node.get_logger().warn(
                    f"{', '.join(loaded.names)} ({loaded.plugin}) did not stop within "
                    f"{STOP_WAIT:g} s (a callback blocks); its entities are undeclared")
                _destroy(loaded)
        with self._lock:
            self._loaded.pop(loaded.unique_id, None)

    def stop_all(self) -> None:
        with self._lock:
            every = list(self._loaded.values())
        for loaded in every:  # asked all at once, then waited for
            loaded.refused = True
            for node in loaded.scope.nodes:
                node.shutdown()
        for loaded in every:
            self.stop(loaded)


_LEVELS = {10: "DEBUG", 20: "INFO", 30: "WARN", 40: "ERROR", 50: "FATAL"}


def _destroy(loaded: Loaded) -> None:
    for node in loaded.scope.nodes:
        with contextlib.suppress(Exception):  # one node's undeclare must not stop the rest
            (node.owner or node).destroy_node()


def _rclpy_context() -> Any:
    from rclpy.context import Context

    context = Context()
    context.init(args=[])
    return context


def run() -> int:
    signal.signal(signal.SIGTERM, signal.default_int_handler)  # stops like Ctrl-C
    node = Node("ComponentManager")
    container = Container(node)
    try:
        node.spin()
    finally:
        container.stop_all()
        node.destroy_node()
    return 0


def main() -> int:
    return reported(run, "component_container")


if __name__ == "__main__":
    sys.exit(main())
