"""The user's bus credentials: one `user:password` line in a 0600 file, made on first use.

Every Zenoh session of launcher (nodes, CLI tools, routers) authenticates with them (Zenoh's
user/password authentication), so another local user, or a host that was not given the
file, is refused even where it can reach a TCP port. The file is also the dictionary a
router checks others against. It is `~/.launcher/credentials`, or the file
LAUNCHER_CREDENTIALS names (copy it to the other hosts of a multi-host graph).
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from pathlib import Path
from typing import NamedTuple

from launcher.errors import Location, ParseError
from launcher.private import create_once

VARIABLE = "LAUNCHER_CREDENTIALS"
USER = "launcher"


class Credentials(NamedTuple):
    user: str
    password: str
    file: Path  # the dictionary that routers and peers check others against


def path(environ: Mapping[str, str] | None = None) -> Path:
    env = os.environ if environ is None else environ
    return Path(env.get(VARIABLE) or Path.home() / ".launcher" / "credentials")


def load(environ: Mapping[str, str] | None = None) -> Credentials:
    """The credentials, made (0600, a random password) when the default file is missing."""
    file = path(environ)
    env = os.environ if environ is None else environ
    if not file.exists() and not env.get(VARIABLE):
        _create(file)
    try:
        text = file.read_text(encoding="utf-8")
    except OSError as exc:
        raise ParseError(f"cannot read the bus credentials: {exc.strerror}",
                         Location(str(file))) from None
    return parse(text, str(file))


def parse(text: str, name: str) -> Credentials:
    """The first `user:password` line (blank lines and `#` comments skipped)."""
    for number, line in enumerate(text.splitlines(), 1):
        stripped = line.strip()
        if not stripped or stripped.startswith("#"):
            continue
        user, colon, password = stripped.partition(":")
        if not colon or not user or not password or any(c.isspace() for c in stripped):
            raise ParseError("expected one line 'user:password' (no spaces), got "
                             f"{stripped[:40]!r}", Location(name, number, 1))
        return Credentials(user, password, Path(name))
    raise ParseError("no 'user:password' line in the bus credentials file", Location(name))


def _create(file: Path) -> None:
    create_once(file, f"{USER}:{os.urandom(24).hex()}\n")
