"""Where the cluster is: none given (embedded), `auto`, `HOST:PORT` (its GCS) or
`ray://HOST:PORT` (Ray Client); and a quick look that something answers there, since Ray
itself retries a dead address for minutes."""

from __future__ import annotations

import socket

from launcher.errors import UsageError

PROBE_SECONDS = 5.0


def probe(address: str, timeout: float = PROBE_SECONDS) -> None:
    """Raise UsageError unless a TCP connection to `address` opens within `timeout`."""
    if address == "auto":
        return
    client = address.startswith("ray://")
    host, sep, port = address.removeprefix("ray://").rpartition(":")
    if not sep or not port.isdigit():
        raise UsageError(f"--address {address}: expected HOST:PORT (10.0.0.1:6379), "
                         "ray://HOST:PORT or auto")
    which = "its Ray Client port (10001 unless set)" if client else \
        "its port (6379 unless set)"
    try:
        socket.create_connection((host.strip("[]"), int(port)), timeout).close()
    except TimeoutError:
        raise UsageError(f"--address {address}: no Ray cluster answers there (nothing "
                         f"answered within {timeout:g} s): is 'ray start --head' running on "
                         f"{host}, and is {port} {which}?") from None
    except OSError as exc:
        why = exc.strerror or str(exc)
        raise UsageError(f"--address {address}: no Ray cluster answers there ({why.lower()}): "
                         f"is 'ray start --head' running on {host}, and is {port} "
                         f"{which}?") from None
