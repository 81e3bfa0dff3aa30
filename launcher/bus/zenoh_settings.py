"""A session's Zenoh settings: key paths and values on launcher's safe defaults, and the JSON5
text Zenoh's config takes for each.

Plain Python: the credentials are read only where an endpoint leaves this host, and the
values (booleans, numbers, strings, lists and maps of them) are written here rather than
through `json`, whose import of `re` alone is a fifth of the listing commands' fast path
(cli/quick.py; bench/commands measures it).
"""

from __future__ import annotations

from launcher.bus.places import DEFAULT_TIMEOUT, TYPE_CHECKING, is_local

if TYPE_CHECKING:
    from collections.abc import Mapping


def settings(mode: str, listen: list[str], connect: list[str],
             timeout_s: float = DEFAULT_TIMEOUT,
             environ: Mapping[str, str] | None = None,
             check_others: bool = False) -> dict[str, object]:
    """The config as key paths and values (also written out for other Zenoh programs).
    Credentials are presented where a connect endpoint leaves this host; `check_others` (a
    router listening beyond it) checks those who connect against them."""
    values: dict[str, object] = {
        "mode": mode,
        "scouting/multicast/enabled": False,
        "scouting/gossip/enabled": True,
        "scouting/delay": 0,
        # as rmw_zenoh's default config: advanced publishers (latched topics) need it
        "timestamping/enabled": {"router": True, "peer": True, "client": True},
        "listen/endpoints": listen,
        "connect/endpoints": connect,
    }
    if check_others or any(not is_local(endpoint) for endpoint in connect):
        from launcher.bus import credentials

        secret = credentials.load(environ)
        values["transport/auth/usrpwd"] = (
            {"dictionary_file": str(secret.file)} if check_others else
            {"user": secret.user, "password": secret.password})
    if connect:
        ms = int(timeout_s * 1000)
        values["connect/timeout_ms"] = {"router": ms, "peer": ms, "client": ms}
        values["connect/exit_on_failure"] = {"router": False, "peer": True, "client": True}
        values["connect/retry"] = {"period_init_ms": 20, "period_max_ms": 500,
                                   "period_increase_factor": 2}
    return values


def json5(value: object) -> str:
    """`value` as JSON (which JSON5 reads): None, bool, int, float, str, list and dict."""
    if value is None or isinstance(value, bool):
        return {None: "null", True: "true", False: "false"}[value]
    if isinstance(value, int | float):
        return repr(value)
    if isinstance(value, str):
        return '"' + "".join(_ESCAPES.get(c) or (f"\\u{ord(c):04x}" if c < " " else c)
                             for c in value) + '"'
    if isinstance(value, list | tuple):
        return "[" + ",".join(json5(item) for item in value) + "]"
    if isinstance(value, dict):
        return "{" + ",".join(f"{json5(str(k))}:{json5(v)}" for k, v in value.items()) + "}"
    raise TypeError(f"no JSON for {type(value).__name__}")


_ESCAPES = {'"': '\\"', "\\": "\\\\", "\n": "\\n", "\r": "\\r", "\t": "\\t"}
