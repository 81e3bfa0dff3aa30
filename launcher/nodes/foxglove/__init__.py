"""foxglove_bridge: the graph served to Foxglove over its WebSocket protocol (bridge.py),
behind the graph's token (isolation.py)."""

from __future__ import annotations

import os
import socket
import sys
import threading
from typing import TYPE_CHECKING, Any

from launcher.bus import listen_token, ros_args
from launcher.errors import LaunchError, reported

if TYPE_CHECKING:
    from launcher.nodes.foxglove.assets import Assets
    from launcher.nodes.foxglove.bridge import Bridge, Settings

NAME = "foxglove_bridge"


def main() -> int:
    return reported(_run, NAME)


def _run() -> int:
    from launcher.nodes.foxglove import isolation

    token_wanted = _token_wanted()
    if token_wanted:  # (while this process has one thread: before the graph's session)
        if threading.active_count() != 1 or len(os.listdir("/proc/self/task")) != 1:
            raise LaunchError("foxglove_bridge: the private network must be made before "
                              "any thread starts")
        isolation.enter_user_namespace()
    import foxglove

    from launcher.bus.node import Node
    from launcher.nodes.foxglove.assets import Assets
    from launcher.nodes.foxglove.bridge import SYNC_PERIOD, Bridge, Settings

    node = Node(NAME)
    try:
        settings = Settings(node)
        bridge = Bridge(node, settings)
        options = _server_options(bridge, settings, Assets(settings.asset_allowlist,
                                                           _packages()))
        front = None
        if token_wanted:
            token = listen_token.load()
            public = isolation.listen(settings.address, settings.port)
            network = isolation.PrivateNetwork()
            bridge.server = network.call(lambda: foxglove.start_server(
                host="127.0.0.1", port=0, **options))
            inner = bridge.server.port
            front = isolation.Front(public, token, lambda: network.call(
                lambda: socket.create_connection(("127.0.0.1", inner), timeout=5)),
                node.get_logger().warning)
        else:
            token = None
            node.get_logger().warning(f"foxglove_bridge: {listen_token.OFF_WARNING}")
            bridge.server = _start_open(settings, options)
        if settings.use_sim_time:
            node.create_subscription("rosgraph_msgs/msg/Clock", "/clock", bridge.on_clock)
        bridge.sync()
        node.create_timer(SYNC_PERIOD, bridge.sync)
        host = f"[{settings.address}]" if ":" in settings.address else settings.address
        url = listen_token.url(f"ws://{host}:{settings.port}/", token)
        node.get_logger().info(f"Server listening on port {settings.port}")
        print(f"[{NAME}] Foxglove connects to {url}", file=sys.stderr, flush=True)
        node.spin()
        if front is not None:
            front.close()
        bridge.server.stop()
    finally:
        node.destroy_node()
    return 0


def _token_wanted() -> bool:
    """The `token` parameter (read before the node is made: the private network comes
    first) and LAUNCHER_NO_TOKEN."""
    if listen_token.off():
        return False
    parsed = ros_args.parse(sys.argv[1:])
    value = ros_args.node_parameters(parsed, parsed.node_name or NAME,
                                     parsed.namespace or "").get("token", True)
    return str(value).lower() not in ("false", "0", "no", "off")


def _server_options(bridge: Bridge, settings: Settings, assets: Assets) -> dict[str, Any]:
    from foxglove.websocket import Capability

    from launcher.nodes.foxglove.bridge import listener

    wanted = settings.capabilities
    capabilities = [capability for name, capability in (
        ("clientPublish", Capability.ClientPublish), ("parameters", Capability.Parameters),
        ("services", Capability.Services), ("connectionGraph", Capability.ConnectionGraph))
        if name in wanted]
    if settings.use_sim_time:
        capabilities.append(Capability.Time)
    return {"name": NAME, "capabilities": capabilities, "server_listener": listener(bridge),
            "supported_encodings": ["cdr"],
            "asset_handler": assets.fetch if "assets" in wanted else None,
            "message_backlog_size": settings.backlog}


def _start_open(settings: Settings, options: dict[str, Any]) -> Any:
    import foxglove

    try:
        return foxglove.start_server(host=settings.address, port=settings.port, **options)
    except Exception as exc:  # noqa: BLE001 - the SDK's (a taken port)
        raise LaunchError(f"foxglove_bridge cannot listen on {settings.address} port "
                          f"{settings.port}: {exc}") from None


def _packages() -> Any:
    from launcher.packages.index import PackageIndex

    return PackageIndex.from_environment(os.environ)


if __name__ == "__main__":
    sys.exit(main())
