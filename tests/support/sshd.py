"""Real OpenSSH hosts for tests: an sshd in each network namespace of a private network.

`SshHosts(root)` makes a network (tests/support/netns.py) of a launching host and the remote
hosts, and starts each host's `/usr/sbin/sshd` in the host's namespace with its own host key,
its own hostname (a UTS namespace), its own home for root, and its own run folder: a tmpfs
mounted in a mount namespace of the host's, so no Unix socket of one host is reachable from
another through the filesystem the hosts otherwise share (tests/support/sshd_server.py). One user key logs in as root on every host; the client
configuration `<root>/ssh_config` names each host, so that, run in the launching host's
namespace, `ssh -F <root>/ssh_config robot2 hostname` prints `robot2`, as it would for a user.
"""

from __future__ import annotations

import os
import shlex
import shutil
import signal
import subprocess
from collections.abc import Mapping, Sequence
from pathlib import Path

import psutil
import pytest

from tests.support.environment import REQUIRE_EXTERNAL
from tests.support.netns import Network, end_all
from tests.support.sshd_server import RUN_VARIABLE, SSHD, Sshd, keygen

LAUNCHING = "launching"  # the host a test runs the launcher on


def require() -> None:
    """Skips the test where the hosts cannot be made: without root (as test_hosts.py), or
    without OpenSSH, which the set-up installs for the tests (so that is a failure under
    LAUNCHER_REQUIRE_EXTERNAL=1, as in CI)."""
    if os.geteuid() != 0:
        pytest.skip("ssh hosts need root (network namespaces, mounts, sshd)")
    missing = [tool for tool in (SSHD, "ssh", "ssh-keygen", "ip", "unshare")
               if shutil.which(tool) is None]
    if not missing:
        return
    message = (f"ssh hosts need {', '.join(missing)}, which the set-up installs (sh "
               f"hooks/bootstrap.sh test; or apt-get install openssh-server openssh-client)")
    if os.environ.get(REQUIRE_EXTERNAL) == "1":
        pytest.fail(f"{message}; {REQUIRE_EXTERNAL}=1 makes that a failure")
    pytest.skip(message)


class SshHosts:
    """`names` as OpenSSH hosts on a private network with a launching host, all of them
    ended and removed on exit (whatever the test did to them)."""

    def __init__(self, root: Path, names: Sequence[str] = ("robot1", "robot2", "robot3")):
        self.root = root
        self.names = tuple(names)
        self.network = Network((LAUNCHING, *self.names))
        self.config = root / "ssh_config"
        self.known_hosts = root / "known_hosts"
        self.user_key = root / "user_key"
        self.ssh_command = f"ssh -F {self.config}"  # what LAUNCHER_SSH_COMMAND is set to
        self.sshd: dict[str, Sshd] = {}

    def __enter__(self) -> SshHosts:
        self.network.__enter__()
        try:
            self.set_up()
        except BaseException:
            self.__exit__()
            raise
        return self

    def __exit__(self, *exc: object) -> None:
        # Connections first, while their listening sshd is there to reap them (an orphan
        # waits on PID 1, which may be slow to reap or never do)
        for name, server in self.sshd.items():
            if server.process is not None:
                server.process.send_signal(signal.SIGCONT)  # (a frozen one reaps nothing)
            self.end_sessions(name)
            server.stop()
        self.network.remove()

    def set_up(self) -> None:
        self.root.mkdir(parents=True, exist_ok=True)
        os.makedirs("/run/sshd", mode=0o755, exist_ok=True)  # sshd's privilege separation
        keygen(self.user_key, "launcher-tests")
        user_key = (self.root / "user_key.pub").read_text()
        for name in self.names:
            self.sshd[name] = Sshd(self.network.hosts[name], self.root / name, user_key)
        self.known_hosts.write_text(self.known_hosts_text({}))
        self.config.write_text(self.client_config())
        for server in self.sshd.values():
            server.start()

    # Where things are
    @property
    def launcher_namespace(self) -> str:
        return self.network.hosts[LAUNCHING].namespace

    @property
    def launcher_address(self) -> str:
        return self.network.hosts[LAUNCHING].address

    def address(self, name: str) -> str:
        return self.network.hosts[name].address

    def run_folder(self, name: str) -> Path:
        """The host's LAUNCHER_RUN_DIR: a path every host has, with this host's files only."""
        return self.sshd[name].run_folder

    def home(self, name: str) -> Path:
        """Root's home on the host: a folder of its own (visible to all, unlike its run folder)."""
        return self.sshd[name].home

    def in_launching(self, argv: Sequence[str]) -> list[str]:
        """`argv` run on the launching host."""
        return ["ip", "netns", "exec", self.launcher_namespace, *argv]

    def ssh(self, name: str, command: str, *options: str,
            timeout: float = 60) -> subprocess.CompletedProcess:
        """`ssh -F <root>/ssh_config [options] name command` from the launching host."""
        argv = [*shlex.split(self.ssh_command), *options, name, command]
        return subprocess.run(self.in_launching(argv), capture_output=True, text=True,
                              timeout=timeout, stdin=subprocess.DEVNULL)

    def processes_in(self, name: str) -> list[psutil.Process]:
        """Every process on the host but its listening sshd (a connection's sshd counts);
        on the launching host (LAUNCHING), every process."""
        server = self.sshd[name].process if name in self.sshd else None
        return [p for p in self.network.processes_in(name)
                if server is None or p.pid != server.pid]

    def end_sessions(self, name: str) -> None:
        """Ends every process on the host but its listening sshd."""
        end_all(lambda: self.processes_in(name))

    # The host's own set-up
    def set_environment(self, name: str, values: Mapping[str, str]) -> None:
        """The environment the host gives every login (sshd's SetEnv; its run folder stays)."""
        server = self.sshd[name]
        server.environment = {RUN_VARIABLE: str(server.run_folder), **values}
        server.write_config()
        if server.process is not None:
            server.reload()

    def env_loader(self, name: str, values: Mapping[str, str]) -> Path:
        """An env-loader script on the host (roslaunch's kind): exports `values`, then runs
        its arguments."""
        path = self.root / name / "env-loader"
        exports = "".join(f"export {k}={shlex.quote(v)}\n" for k, v in values.items())
        path.write_text(f'#!/bin/sh\n{exports}exec "$@"\n')
        path.chmod(0o755)
        return path

    # Faults
    def cut(self, name: str) -> None:
        self.network.cut(name)

    def restore(self, name: str) -> None:
        self.network.restore(name)

    def stop_sshd(self, name: str) -> None:
        """Nothing listens on the host's port 22: a connection is refused. Open connections
        stay (their sshd processes are the connections')."""
        self.sshd[name].stop()

    def start_sshd(self, name: str) -> None:
        """After stop_sshd; the host's run folder starts empty again."""
        self.sshd[name].start()

    def freeze(self, name: str) -> None:
        """The listening sshd stopped (SIGSTOP): a connection is accepted and never answered."""
        self.sshd[name].signal(signal.SIGSTOP)

    def thaw(self, name: str) -> None:
        self.sshd[name].signal(signal.SIGCONT)

    def refuse_login(self, name: str) -> None:
        """The host's authorized_keys no longer holds the user key: logging in fails."""
        self.sshd[name].authorized_keys.write_text("")

    def allow_login(self, name: str) -> None:
        self.sshd[name].authorized_keys.write_text((self.root / "user_key.pub").read_text())

    def wrong_known_hosts(self, name: str) -> str:
        """An ssh command whose known_hosts holds another key for `name` (the others right)."""
        other = self.root / "other_hostkey"
        if not other.exists():
            keygen(other, "another-host")
        wrong = " ".join((self.root / "other_hostkey.pub").read_text().split()[:2])
        path = self.root / f"known_hosts-wrong-{name}"
        path.write_text(self.known_hosts_text({name: wrong}))
        return f"{self.ssh_command} -o UserKnownHostsFile={path}"

    # Client files
    def known_hosts_text(self, keys: Mapping[str, str]) -> str:
        return "".join(f"{name},{self.address(name)} {keys.get(name, server.host_key)}\n"
                       for name, server in self.sshd.items())

    def client_config(self) -> str:
        hosts = "".join(f"Host {name} {self.address(name)}\n    HostName {self.address(name)}\n"
                        for name in self.names)
        return hosts + (f'Host *\n    User root\n    IdentityFile "{self.user_key}"\n'
                        f"    IdentitiesOnly yes\n"
                        f'    UserKnownHostsFile "{self.known_hosts}"\n'
                        f"    GlobalKnownHostsFile /dev/null\n    BatchMode yes\n")
