"""One host's OpenSSH server for tests (tests/support/sshd.py puts several on a network).

`/usr/sbin/sshd` runs in the host's network namespace and, through `unshare`, in a UTS and a
mount namespace of its own: its hostname is the host's name, its run folder is a tmpfs that
only its processes see, and root's home is a folder of the host's (a passwd file bound over
/etc/passwd there), so a login runs no shell set-up of the machine's. Each connection's
processes are sshd's children, so they share those namespaces: a login on robot2 says `robot2`
and finds robot2's run folder and home, and nothing of robot1's.
"""

from __future__ import annotations

import functools
import signal
import subprocess
import time
from pathlib import Path

from tests.support.netns import Host

SSHD = "/usr/sbin/sshd"
BASE_PATH = "/usr/sbin:/usr/bin:/sbin:/bin"
RUN_VARIABLE = "LAUNCHER_RUN_DIR"  # launcher's run folder (launcher/bus/places.py)
LISTENING = "Server listening on"  # what sshd -e says once its socket is open
# Each start in the host's namespaces: its hostname, its private run folder, its passwd (and,
# where root's password is locked, a shadow entry that sshd accepts: see root_is_locked)
START = ('hostname "$1" && mount -t tmpfs -o mode=0700 tmpfs "$2" && '
         'mount --bind "$3" /etc/passwd && { [ -z "$4" ] || mount --bind "$4" /etc/shadow; } && '
         'exec "$5" -D -e -f "$6"')


class Sshd:
    """One host's OpenSSH server: its files under `folder`, its process in the host's
    namespaces."""

    def __init__(self, host: Host, folder: Path, user_key: str) -> None:
        self.host = host
        self.folder = folder
        self.run_folder = folder / "run"
        self.run_folder.mkdir(parents=True)
        self.home = folder / "home"
        self.home.mkdir(mode=0o700)
        self.config = folder / "sshd_config"
        self.log = folder / "sshd.log"
        self.authorized_keys = folder / "authorized_keys"
        self.authorized_keys.write_text(user_key)
        self.environment = {RUN_VARIABLE: str(self.run_folder)}
        self.process: subprocess.Popen | None = None
        keygen(folder / "hostkey", host.name)
        self.write_config()

    @property
    def host_key(self) -> str:
        """`type base64` of the host key, as known_hosts holds it."""
        return " ".join((self.folder / "hostkey.pub").read_text().split()[:2])

    def write_config(self) -> None:
        unquotable = [k for k, v in self.environment.items() if '"' in k + v or "\n" in k + v]
        if unquotable:
            raise ValueError(f"sshd's SetEnv cannot carry a double quote or a newline: "
                             f"{unquotable}")
        # (sshd takes only the first SetEnv line: every variable goes on that one)
        variables = " ".join(f'"{k}={v}"' for k, v in self.environment.items())
        lines = [f"ListenAddress {self.host.address}", f"HostKey {self.folder / 'hostkey'}",
                 f"PidFile {self.folder / 'sshd.pid'}",
                 f"AuthorizedKeysFile {self.authorized_keys}", "StrictModes no", "UsePAM no",
                 "PermitRootLogin prohibit-password", "PasswordAuthentication no",
                 "KbdInteractiveAuthentication no", "X11Forwarding no", "PrintMotd no",
                 f"SetEnv {variables}"]
        if knows_per_source_penalties():
            lines.append("PerSourcePenalties no")  # (failed logins must not lock tests out)
        self.config.write_text("\n".join(lines) + "\n")

    def start(self) -> None:
        shadow = unlocked_shadow(self.folder) if root_is_locked() else ""
        argv = ["ip", "netns", "exec", self.host.namespace, "unshare", "--uts", "--mount",
                "sh", "-c", START, "sshd-host", self.host.name, str(self.run_folder),
                str(own_passwd(self.folder, self.home)), str(shadow), SSHD, str(self.config)]
        heard = self.times_listening()
        with open(self.log, "a") as log:  # (a pipe would fill and block sshd)
            # ip netns exec, unshare and sh each exec the next: the child is sshd itself
            self.process = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=log,
                                            stderr=subprocess.STDOUT, start_new_session=True,
                                            env={"PATH": BASE_PATH})
        self.wait_listening(heard)

    def reload(self) -> None:
        """sshd reads its configuration again (SIGHUP: it execs itself, same namespaces)."""
        heard = self.times_listening()
        self.signal(signal.SIGHUP)
        self.wait_listening(heard)

    def stop(self) -> None:
        if self.process is None:
            return
        self.process.send_signal(signal.SIGCONT)  # (a frozen one must see its SIGTERM)
        self.process.terminate()
        try:
            self.process.wait(10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait(10)
        self.process = None

    def signal(self, sig: int) -> None:
        if self.process is None:
            raise RuntimeError(f"the sshd of {self.host.name} is stopped")
        self.process.send_signal(sig)

    def times_listening(self) -> int:
        return self.log.read_text().count(LISTENING) if self.log.exists() else 0

    def wait_listening(self, heard: int, timeout: float = 20.0) -> None:
        deadline = time.monotonic() + timeout
        while self.times_listening() <= heard:
            if self.process is None or self.process.poll() is not None or \
                    time.monotonic() > deadline:
                raise RuntimeError(f"the sshd of {self.host.name} did not start listening; "
                                   f"its log ({self.log}):\n{self.log.read_text()}")
            time.sleep(0.02)


def keygen(path: Path, comment: str) -> None:
    done = subprocess.run(["ssh-keygen", "-q", "-t", "ed25519", "-N", "", "-C", comment,
                           "-f", str(path)], capture_output=True, text=True, timeout=30)
    if done.returncode != 0:
        raise RuntimeError(f"ssh-keygen -f {path}: {done.stderr.strip()}")


@functools.cache
def knows_per_source_penalties() -> bool:
    """OpenSSH 9.8 and later penalise addresses with failed logins; older ones refuse the
    option ("Bad configuration option"), so it is given only to an sshd that takes it."""
    done = subprocess.run([SSHD, "-T", "-f", "/dev/null", "-o", "PerSourcePenalties=no"],
                          capture_output=True, text=True, timeout=30)
    return "Bad configuration option" not in done.stderr


def own_passwd(folder: Path, home: Path) -> Path:
    """The machine's passwd with root's home moved to `home`: what the host's logins start
    in, with the host's own shell set-up (none), not the machine's (~/.bashrc may run a
    version manager that a killed login leaves locked for the next)."""
    lines = Path("/etc/passwd").read_text().splitlines()
    own = [":".join([*f[:5], str(home), *f[6:]]) if f[0] == "root" else ":".join(f)
           for f in (line.split(":") for line in lines)]
    path = folder / "passwd"
    path.write_text("\n".join(own) + "\n")
    return path


@functools.cache
def root_is_locked() -> bool:
    """A `!` before root's password hash locks the account, which sshd without PAM also
    refuses a key for."""
    return root_shadow_entry().split(":")[1].startswith("!")


def root_shadow_entry() -> str:
    with open("/etc/shadow") as shadow:
        return next(line for line in shadow if line.startswith("root:"))


def unlocked_shadow(folder: Path) -> Path:
    """A shadow file of root's entry alone, unlocked and without a password (no login by
    password, which the hosts refuse anyway), for the host's mount namespace: the machine's
    own /etc/shadow is never changed."""
    fields = root_shadow_entry().rstrip("\n").split(":")
    fields[1] = "*"
    path = folder / "shadow"
    path.write_text(":".join(fields) + "\n")
    path.chmod(0o600)
    return path
