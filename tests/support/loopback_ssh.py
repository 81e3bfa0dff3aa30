"""An `ssh` that logs into this host itself, for tests of the link without an sshd or root
(LAUNCHER_SSH_COMMAND="python loopback_ssh.py"): it passes over ssh's options, and runs the
remote command with /bin/sh -c, as sshd runs it through the login shell. The "remote" login
gets a fresh environment, as a login does: HOME, PATH, SSH_CONNECTION, and each LOOPBACK_NAME
variable given to it as NAME (its own run folder, package path, …)."""

from __future__ import annotations

import os
import sys

TAKES_VALUE = set("BbcDEeFIiJLlmOoPpQRSWw")


def main(argv: list[str]) -> int:
    words, at = argv[1:], 0
    while at < len(words) and words[at].startswith("-") and words[at] != "--":
        option = words[at]
        at += 2 if option[1:] and option[-1] in TAKES_VALUE and len(option) == 2 else 1
    if at < len(words) and words[at] == "--":
        at += 1
    address, command = words[at], " ".join(words[at + 1:])
    if address.endswith(".silent"):  # (a host that takes the connection and never answers)
        import time
        time.sleep(120)
        return 255
    if address.endswith(".unreachable"):  # (what a host that never answers looks like)
        print(f"ssh: connect to host {address} port 22: Connection timed out", file=sys.stderr)
        return 255
    env = {"HOME": os.environ.get("HOME", "/"), "PATH": os.environ.get("PATH", "/usr/bin:/bin"),
           "SSH_CONNECTION": "127.0.0.1 40000 127.0.0.1 22"}
    env.update({name[len("LOOPBACK_"):]: value for name, value in os.environ.items()
                if name.startswith("LOOPBACK_")})
    os.execve("/bin/sh", ["/bin/sh", "-c", command], env)
    return 127


if __name__ == "__main__":
    sys.exit(main(sys.argv))
