"""The graph's token: the secret every TCP listener of launcher asks for (the web viewer's
page and stream, the foxglove bridge), so that another local user, who can reach any
loopback port, reaches none of them.

One token per graph (per user and ROS_DOMAIN_ID), in `<run folder>/domain-<N>.token`, 0600
in the user's 0700 run folder, made on first use. A client presents it as Jupyter's do:
`?token=…` in the URL launcher prints; a browser that opened that URL is given a cookie
(`launcher_token_<port>`: one per port, so graphs on other ports do not clobber it), and an
`Authorization: Bearer …` header is taken too. LAUNCHER_NO_TOKEN=1 (or a listener's own
option) turns the check off, for a listener bound on purpose to a private network: each
listener warns when it is off.
"""

from __future__ import annotations

import hmac
import os
import secrets
from collections.abc import Mapping
from http.cookies import CookieError, SimpleCookie
from pathlib import Path
from urllib.parse import parse_qs, urlsplit

from launcher.bus import discovery
from launcher.private import create_once

QUERY = "token"
OFF_VARIABLE = "LAUNCHER_NO_TOKEN"
OFF_WARNING = ("the token check is off: anyone who can reach this port can watch and command "
               "the graph through it")


def path(environ: Mapping[str, str] | None = None) -> Path:
    return discovery.socket_path(environ).with_suffix(".token")


def load(environ: Mapping[str, str] | None = None) -> str:
    """The graph's token, made (0600) when there is none yet."""
    file = path(environ)
    if not file.exists():
        create_once(file, secrets.token_urlsafe(24) + "\n")
    return file.read_text(encoding="utf-8").strip()


def off(environ: Mapping[str, str] | None = None) -> bool:
    """Whether LAUNCHER_NO_TOKEN asks for no token check."""
    env = os.environ if environ is None else environ
    return env.get(OFF_VARIABLE, "").strip().lower() in ("1", "true", "yes", "on")


def cookie_name(port: int) -> str:
    return f"launcher_token_{port}"


def url(base: str, token: str | None) -> str:
    """`base` with the token in its query (as printed to the user); `base` alone without."""
    if not token:
        return base
    return f"{base}{'&' if '?' in base else '?'}{QUERY}={token}"


def presented(target: str, headers: Mapping[str, str] | list[tuple[str, str]],
              port: int) -> tuple[str | None, bool]:
    """The token a request presents (its URL's query, its cookie for `port`, or a bearer
    header), and whether it came in the URL (then the answer sets the cookie)."""
    query = parse_qs(urlsplit(target).query).get(QUERY)
    if query:
        return query[0], True
    items = headers.items() if isinstance(headers, Mapping) else headers
    for key, value in items:
        name = key.lower()
        if name == "cookie":
            try:
                jar = SimpleCookie(value)
            except CookieError:
                continue
            if cookie_name(port) in jar:
                return jar[cookie_name(port)].value, False
        elif name == "authorization" and value.lower().startswith("bearer "):
            return value[7:].strip(), False
    return None, False


def matches(given: str | None, token: str) -> bool:
    return given is not None and hmac.compare_digest(given.encode(), token.encode())


def set_cookie(port: int, token: str) -> str:
    """The Set-Cookie value for a browser that came with the token in its URL."""
    return f"{cookie_name(port)}={token}; Path=/; HttpOnly; SameSite=Strict"


REFUSAL = """<!doctype html><meta charset="utf-8"><title>launcher: token required</title>
<h1>This port needs the graph's token</h1>
<p>launcher's listeners answer only those who hold the token of the graph they serve. Open
the address launcher printed, which ends in <code>?token=…</code>; the token is also in the
file {file}, which only its owner can read.</p>
"""


def refusal(environ: Mapping[str, str] | None = None) -> str:
    """The page a request without the token gets (403)."""
    return REFUSAL.format(file=path(environ))
