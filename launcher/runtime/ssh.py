"""How a launch reaches another host: the user's own OpenSSH client, its command line, and what
its failures mean in words.

The client is `ssh`, or the command in LAUNCHER_SSH_COMMAND (as git's GIT_SSH_COMMAND), so the
user's ~/.ssh/config, agent and known_hosts apply. The options given here only make it fit a
program: no prompt (BatchMode: a key or the agent, never a password), no forwarding, one
connection per host shared by everything sent there (ControlMaster), and keepalives. Host keys
are never accepted on the user's behalf: with BatchMode OpenSSH refuses an unknown or changed
key, and launcher says why.
"""

from __future__ import annotations

import re
import shlex
from collections.abc import Mapping

from launcher.runtime.machine import Machine

VARIABLE = "LAUNCHER_SSH_COMMAND"
NO_LAUNCHER = "launcher-remote: no-launcher"
NO_ENV_LOADER = "launcher-remote: no-env-loader"


def client(environ: Mapping[str, str]) -> list[str]:
    """The ssh command the user chose (LAUNCHER_SSH_COMMAND), split as a shell would."""
    return shlex.split(environ.get(VARIABLE) or "ssh")


def argv(machine: Machine, control_path: str, environ: Mapping[str, str]) -> list[str]:
    """The command line that opens `machine`'s one connection and starts the supervisor."""
    timeout = max(1, round(machine.timeout))
    options = ["-T", "-x", "-e", "none",
               "-o", "BatchMode=yes",
               # (never a key accepted for the user, whatever a config file's "accept-new")
               "-o", "StrictHostKeyChecking=yes",
               "-o", "ControlMaster=auto", "-o", f"ControlPath={control_path}",
               "-o", "ControlPersist=no",
               "-o", f"ConnectTimeout={timeout}",
               "-o", "ServerAliveInterval=1", "-o", "ServerAliveCountMax=3",
               "-o", "ClearAllForwardings=yes", "-o", "ForwardAgent=no",
               "-o", "PermitLocalCommand=no"]
    if machine.ssh_port is not None:
        options += ["-p", str(machine.ssh_port)]
    if machine.user:
        options += ["-l", machine.user]
    return [*client(environ), *options, "--", machine.address, remote_command(machine)]


def remote_command(machine: Machine) -> str:
    """What the remote login runs: a POSIX shell (whatever the user's login shell is) that
    starts the supervisor through the env-loader, if any, saying which of the two is missing."""
    find = (f"command -v launcher >/dev/null 2>&1 || {{ echo '{NO_LAUNCHER}' >&2; exit 127; }};"
            " exec launcher remote-supervisor")
    inner = f"exec /bin/sh -c {shlex.quote(find)}"
    if machine.env_loader:
        loader = shlex.quote(machine.env_loader)
        inner = (f"[ -x {loader} ] || {{ echo '{NO_ENV_LOADER}' >&2; exit 127; }}; "
                 f"exec {loader} /bin/sh -c {shlex.quote(find)}")
    return f"exec /bin/sh -c {shlex.quote(inner)}"


def describe(machine: Machine) -> str:
    """`machine 'robot2' (pi@10.0.0.2:2222)`, as errors name it."""
    place = f"{machine.user}@{machine.address}" if machine.user else machine.address
    if machine.ssh_port is not None:
        place += f":{machine.ssh_port}"
    return f"machine '{machine.name}' ({place})"


def explain(machine: Machine, code: int | None, stderr: str) -> str:
    """What went wrong, in words, from ssh's exit status and what it printed."""
    name, address = describe(machine), machine.address
    login = f"{machine.user}@{address}" if machine.user else address
    lines = [line.strip() for line in stderr.splitlines() if line.strip()]
    text = "\n".join(lines)
    if NO_ENV_LOADER in text:
        return (f"{name}: env-loader '{machine.env_loader}' does not exist there or is not "
                "executable")
    if NO_LAUNCHER in text:
        given = "its login and env-loader give" if machine.env_loader else "its login gives"
        return (f"{name}: launcher is not installed there, or not on the PATH {given}; "
                "install the same launcher there")
    if machine.env_loader and code not in (None, 0, 255):  # (255: ssh's own failures)
        said = "; ".join(lines[-5:]) if lines else "it printed nothing"
        return f"{name}: env-loader '{machine.env_loader}' failed there (exit {code}): {said}"
    if "Could not resolve hostname" in text or "Name or service not known" in text:
        return (f"{name}: cannot resolve '{address}' (is it in DNS, /etc/hosts or "
                "~/.ssh/config?)")
    if "Connection refused" in text:
        return (f"{name}: {address} refused the connection on port "
                f"{machine.ssh_port or 22}: is sshd running there, and is ssh-port right?")
    if "REMOTE HOST IDENTIFICATION HAS CHANGED" in text or (
            "Host key for" in text and "has changed" in text):
        offending = re.search(r"Offending \S+ key in (\S+)", text)
        where = f" ({offending.group(1)})" if offending else ""
        return (f"{name}: the host key of {address} does not match known_hosts{where}: an "
                "attack, or a reinstalled host; launcher never overrides it (if it was "
                f"reinstalled: ssh-keygen -R {address}, then log in once with ssh and check "
                "its fingerprint)")
    if "Host key verification failed" in text or "host key is known" in text:
        return (f"{name}: {address} is not in your known_hosts; launcher never accepts a host "
                f"key for you: log in once with 'ssh {login}' and check its fingerprint")
    if "Permission denied" in text:
        return (f"{name}: logging in as {login} failed ({_methods(text)}): launcher uses your "
                f"keys and ssh-agent, never a password; check that 'ssh {login} true' works "
                "without a prompt")
    if "timed out" in text or "Connection timed out" in text:
        return (f"{name}: {address} did not answer within {machine.timeout:g} s "
                "(timeout=)")
    said = "; ".join(lines[-3:]) if lines else "nothing"
    status = "" if code is None else f" (ssh exited with {code})"
    return f"{name}: the connection failed{status}; ssh said: {said}"


def _methods(text: str) -> str:
    found = re.search(r"Permission denied \(([^)]*)\)", text)
    return found.group(1) if found else "no accepted key"
