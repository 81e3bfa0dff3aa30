"""foxglove_bridge: the graph served to Foxglove over its WebSocket protocol (bridge.py),
through launcher's front (front.py), which asks for the graph's token; the SDK's server in a
private network that the front alone reaches (isolation.py)."""

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
    from launcher.nodes.foxglove.bridge import Bridge
    from launcher.nodes.foxglove.settings import Settings

NAME = "foxglove_bridge"


def main() -> int:
    return reported(_run, NAME)


def _run() -> int:
    from launcher.nodes.foxglove import front, isolation

    token_wanted = _token_wanted()
    if token_wanted:  # (while this process has one thread: before the graph's session)
        if threading.active_count() != 1 or len(os.listdir("/proc/self/task")) != 1:
            raise LaunchError("foxglove_bridge: the private network must be made before "
                              "any thread starts")
        isolation.enter_user_namespace()
    import foxglove

    from launcher.bus.node import Node
    from launcher.nodes.foxglove.assets import Assets
    from launcher.nodes.foxglove.bridge import SYNC_PERIOD, Bridge
    from launcher.nodes.foxglove.settings import Settings

    node = Node(NAME)
    try:
        settings = Settings(node)
        bridge = Bridge(node, settings)
        options = _server_options(bridge, settings, Assets(settings.asset_allowlist,
                                                           _packages()))
        public = front.listen(settings.address, settings.port)
        if token_wanted:
            token: str | None = listen_token.load()
            network = isolation.PrivateNetwork()
            bridge.server = network.call(lambda: foxglove.start_server(
                host="127.0.0.1", port=0, **options))
            inner = bridge.server.port

            def connect() -> socket.socket:
                return network.call(lambda: socket.create_connection(("127.0.0.1", inner),
                                                                     timeout=5))
        else:  # (the SDK's server on the host's loopback: anyone may reach it anyway)
            token = None
            node.get_logger().warning(f"foxglove_bridge: {listen_token.OFF_WARNING}")
            bridge.server = foxglove.start_server(host="127.0.0.1", port=0, **options)
            inner = bridge.server.port

            def connect() -> socket.socket:
                return socket.create_connection(("127.0.0.1", inner), timeout=5)
        door = front.Front(public, token, connect, node.get_logger().warning)
        if settings.use_sim_time:
            node.create_subscription("rosgraph_msgs/msg/Clock", "/clock", bridge.on_clock)
        bridge.sync()
        node.create_timer(SYNC_PERIOD, bridge.sync)
        host = f"[{settings.address}]" if ":" in settings.address else settings.address
        url = listen_token.url(f"ws://{host}:{settings.port}/", token)
        node.get_logger().info(f"Server listening on port {settings.port}")
        print(f"[{NAME}] Foxglove connects to {url}", file=sys.stderr, flush=True)
        node.spin()
        door.close()
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

    from launcher.nodes.foxglove.listener import Listener

    wanted = settings.capabilities
    capabilities = [capability for name, capability in (
        ("clientPublish", Capability.ClientPublish), ("parameters", Capability.Parameters),
        ("services", Capability.Services), ("connectionGraph", Capability.ConnectionGraph))
        if name in wanted]
    if settings.use_sim_time:
        capabilities.append(Capability.Time)
    return {"name": NAME, "capabilities": capabilities, "server_listener": Listener(bridge),
            "supported_encodings": ["cdr"],
            "asset_handler": assets.fetch if "assets" in wanted else None,
            "message_backlog_size": settings.backlog}


def _packages() -> Any:
    from launcher.packages.index import PackageIndex

    return PackageIndex.from_environment(os.environ)


if __name__ == "__main__":
    sys.exit(main())
