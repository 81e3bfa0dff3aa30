"""The OpenSSH hosts the multi-host tests run on (tests/support/sshd.py): each answers ssh as
a host of its own, reaches the others over the network only, drops off when its cable is cut,
and each fault the bad-input tests rely on produces OpenSSH's own words."""

from __future__ import annotations

import shlex
import subprocess
import sys
import time
from pathlib import Path

import psutil
import pytest

from tests.support.environment import REPO
from tests.support.netns import Network
from tests.support.sshd import LAUNCHING, SshHosts, require
from tests.support.waiting import wait_for

NAMES = ("robot1", "robot2", "robot3")
QUICK = ("-o", "ConnectTimeout=2")  # the faults that hang do so for this long


@pytest.mark.parametrize("name", NAMES)
def test_each_host_answers_ssh_from_the_launching_host_with_its_own_hostname(ssh_hosts, name):
    done = ssh_hosts.ssh(name, 'echo "$(hostname) $SSH_CONNECTION"')
    assert done.returncode == 0, done.stderr
    hostname, client, _, server, _ = done.stdout.split()
    assert (hostname, client, server) == (name, ssh_hosts.launcher_address,
                                          ssh_hosts.address(name))


def test_a_host_reaches_another_by_its_address(ssh_hosts):
    inner = f"ssh -F {ssh_hosts.config} {ssh_hosts.address('robot3')} " \
            f"'echo \"$(hostname) $SSH_CONNECTION\"'"
    done = ssh_hosts.ssh("robot1", inner)
    assert done.returncode == 0, done.stderr
    hostname, client = done.stdout.split()[:2]
    assert (hostname, client) == ("robot3", ssh_hosts.address("robot1"))


def test_a_file_in_one_hosts_run_folder_is_seen_by_no_other(ssh_hosts):
    folder = ssh_hosts.run_folder("robot1")
    wrote = ssh_hosts.ssh("robot1", 'echo mine > "$LAUNCHER_RUN_DIR/here" && '
                                    'cat "$LAUNCHER_RUN_DIR/here"')
    assert (wrote.returncode, wrote.stdout) == (0, "mine\n"), wrote.stderr
    seen = ssh_hosts.ssh("robot2", f"ls -A {folder}")
    assert (seen.returncode, seen.stdout) == (0, ""), seen.stderr
    assert not list(folder.iterdir())  # nor from the machine itself


def test_each_host_logs_in_to_a_home_of_its_own(ssh_hosts):
    done = ssh_hosts.ssh("robot2", 'echo "$HOME"; pwd')
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines() == [str(ssh_hosts.home("robot2"))] * 2


def test_a_cut_host_cannot_be_reached_until_restored(ssh_hosts):
    ssh_hosts.cut("robot2")
    try:
        cut = ssh_hosts.ssh("robot2", "hostname", *QUICK)
    finally:
        ssh_hosts.restore("robot2")
    assert cut.returncode == 255
    assert cut.stderr.splitlines() == [
        f"ssh: connect to host {ssh_hosts.address('robot2')} port 22: Connection timed out"]
    again = ssh_hosts.ssh("robot2", "hostname")
    assert (again.returncode, again.stdout) == (0, "robot2\n"), again.stderr


def test_a_cut_ends_an_open_connection(ssh_hosts):
    argv = [*shlex.split(ssh_hosts.ssh_command), "-o", "ServerAliveInterval=1", "-o",
            "ServerAliveCountMax=2", "robot2", "echo alive; exec sleep 60"]
    client = subprocess.Popen(ssh_hosts.in_launching(argv), stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True)
    try:
        assert client.stdout.readline() == "alive\n"
        ssh_hosts.cut("robot2")
        _, err = client.communicate(timeout=20)
    finally:
        client.kill()
        client.wait()
        ssh_hosts.restore("robot2")
        ssh_hosts.end_sessions("robot2")  # (its sshd session outlives a cut, as on a robot)
    assert client.returncode == 255
    assert err.splitlines() == [f"Timeout, server {ssh_hosts.address('robot2')} not responding."]


def test_processes_in_counts_a_connection_but_not_the_listening_sshd(ssh_hosts):
    assert ssh_hosts.processes_in("robot3") == []
    argv = [*shlex.split(ssh_hosts.ssh_command), "robot3", "exec sleep 60"]
    client = subprocess.Popen(ssh_hosts.in_launching(argv), stdin=subprocess.DEVNULL)
    try:
        deadline = time.monotonic() + 20
        while not any(p.name() == "sleep" for p in ssh_hosts.processes_in("robot3")):
            assert client.poll() is None and time.monotonic() < deadline
            time.sleep(0.05)
        found = {p.pid: p.name() for p in ssh_hosts.processes_in("robot3")}
    finally:
        client.kill()
        client.wait()
        ssh_hosts.end_sessions("robot3")
    assert ssh_hosts.sshd["robot3"].process.pid not in found
    # the command, and the connection's sshd (sshd-session from OpenSSH 9.8 on)
    assert sorted(found.values())[0] == "sleep"
    assert [n for n in found.values() if n != "sleep"] and \
        all(n.startswith("sshd") for n in found.values() if n != "sleep")
    assert ssh_hosts.processes_in("robot3") == []


def test_a_host_gives_logins_the_environment_set_for_it(ssh_hosts):
    ssh_hosts.set_environment("robot3", {"LAUNCHER_ROUTER_LINGER": "0.5",
                                         "PATH": f"{Path(sys.executable).parent}:/usr/bin:/bin"})
    try:
        done = ssh_hosts.ssh("robot3", 'echo "$LAUNCHER_ROUTER_LINGER $LAUNCHER_RUN_DIR"; '
                                       'command -v launcher')
    finally:
        ssh_hosts.set_environment("robot3", {})
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines() == [f"0.5 {ssh_hosts.run_folder('robot3')}",
                                        str(Path(sys.executable).parent / "launcher")]


def test_an_env_loader_exports_its_values_to_the_command_it_runs(ssh_hosts):
    loader = ssh_hosts.env_loader("robot1", {"LAUNCHER_PACKAGE_PATH": "/ws/src 'quoted'"})
    done = ssh_hosts.ssh("robot1", f"{loader} /bin/sh -c 'echo \"$LAUNCHER_PACKAGE_PATH\"'")
    assert (done.returncode, done.stdout) == (0, "/ws/src 'quoted'\n"), done.stderr


# Each fault as OpenSSH words it (the link's error messages are matched against these lines)
def test_a_stopped_sshd_refuses_the_connection(ssh_hosts):
    ssh_hosts.stop_sshd("robot1")
    try:
        done = ssh_hosts.ssh("robot1", "hostname", *QUICK)
    finally:
        ssh_hosts.start_sshd("robot1")
    assert done.returncode == 255
    assert done.stderr.splitlines() == [
        f"ssh: connect to host {ssh_hosts.address('robot1')} port 22: Connection refused"]


def test_a_frozen_sshd_times_out_during_the_banner_exchange(ssh_hosts):
    ssh_hosts.freeze("robot1")
    try:
        done = ssh_hosts.ssh("robot1", "hostname", *QUICK)
    finally:
        ssh_hosts.thaw("robot1")
    assert done.returncode == 255
    assert done.stderr.splitlines() == [
        "Connection timed out during banner exchange",
        f"Connection to {ssh_hosts.address('robot1')} port 22 timed out"]


def test_a_host_without_the_user_key_denies_the_login(ssh_hosts):
    ssh_hosts.refuse_login("robot2")
    try:
        done = ssh_hosts.ssh("robot2", "hostname")
    finally:
        ssh_hosts.allow_login("robot2")
    assert done.returncode == 255
    assert done.stderr.splitlines() == [
        f"root@{ssh_hosts.address('robot2')}: Permission denied (publickey)."]


def test_a_known_hosts_with_another_key_fails_host_key_verification(ssh_hosts):
    command = ssh_hosts.wrong_known_hosts("robot2")
    known_hosts = shlex.split(command)[-1].removeprefix("UserKnownHostsFile=")
    done = subprocess.run(ssh_hosts.in_launching([*shlex.split(command), "robot2", "hostname"]),
                          capture_output=True, text=True, timeout=60)
    lines = done.stderr.splitlines()
    assert done.returncode == 255
    assert "@    WARNING: REMOTE HOST IDENTIFICATION HAS CHANGED!     @" in lines
    assert f"Offending ED25519 key in {known_hosts}:2" in lines
    assert lines[-2:] == [f"Host key for {ssh_hosts.address('robot2')} has changed and you "
                          f"have requested strict checking.", "Host key verification failed."]


def test_a_host_key_missing_from_known_hosts_fails_verification(ssh_hosts, tmp_path):
    (tmp_path / "known_hosts").write_text("")
    done = ssh_hosts.ssh("robot2", "hostname", "-o",
                         f"UserKnownHostsFile={tmp_path / 'known_hosts'}")
    assert done.returncode == 255
    assert done.stderr.splitlines() == ["Host key verification failed."]


def test_teardown_leaves_no_namespace_and_no_process(tmp_path):
    require()
    with pytest.raises(RuntimeError, match="the test failed"), \
            SshHosts(tmp_path, names=("robot1",)) as hosts:
        session = subprocess.Popen(hosts.in_launching(
            [*shlex.split(hosts.ssh_command), "robot1", "exec sleep 60"]))
        wait_for(lambda: [p for p in hosts.processes_in("robot1") if p.name() == "sleep"], 20)
        hosts.freeze("robot1")
        namespaces = [host.namespace for host in hosts.network.hosts.values()]
        left = [*hosts.network.processes_in("robot1"), *hosts.network.processes_in(LAUNCHING)]
        raise RuntimeError("the test failed")
    session.wait(10)
    listed = subprocess.run(["ip", "netns", "list"], capture_output=True, text=True).stdout
    assert not [ns for ns in [*namespaces, hosts.network.switch] if ns in listed]
    assert [p for p in left if p.is_running()] == []  # nor a zombie: each one reaped


def test_hosts_left_by_a_killed_test_are_removed_by_the_next(tmp_path):
    require()
    script = ("import sys, time; from pathlib import Path; from tests.support.sshd import SshHosts\n"
              "with SshHosts(Path(sys.argv[1]), names=('robot1',)) as hosts:\n"
              "    print(hosts.network.switch, hosts.sshd['robot1'].process.pid, flush=True)\n"
              "    time.sleep(600)\n")
    killed = subprocess.Popen([sys.executable, "-c", script, str(tmp_path)], cwd=REPO,
                              stdout=subprocess.PIPE, text=True)
    switch, pid = killed.stdout.readline().split()
    killed.kill()  # (no teardown runs: its sshd and namespaces stay)
    killed.wait()
    orphan = psutil.Process(int(pid))
    assert running(orphan)
    with Network(("robot1",)):
        pass
    assert switch not in subprocess.run(["ip", "netns", "list"], capture_output=True,
                                        text=True).stdout
    assert not running(orphan)


def test_a_locked_root_account_logs_in_and_the_machine_stays_locked(tmp_path):
    require()
    shadow = tmp_path / "shadow"
    shadow.write_text("root:!:20000:0:99999:7:::\n")
    script = ("import sys; from pathlib import Path; from tests.support.sshd import SshHosts\n"
              "with SshHosts(Path(sys.argv[1]), names=('robot1',)) as hosts:\n"
              "    done = hosts.ssh('robot1', 'hostname')\n"
              "print(done.stdout.strip(), open('/etc/shadow').read().split(':')[1])\n")
    # (the machine's /etc/shadow, as the hosts see it, is this locked one; theirs unlocked)
    done = subprocess.run(["unshare", "--mount", "sh", "-c",
                           'mount --bind "$1" /etc/shadow && exec "$2" -c "$3" "$4"', "sh",
                           str(shadow), sys.executable, script, str(tmp_path / "hosts")],
                          capture_output=True, text=True, timeout=120, cwd=REPO)
    assert (done.returncode, done.stdout) == (0, "robot1 !\n"), done.stderr


def running(proc: psutil.Process) -> bool:
    """Not ended (a zombie whose reaper is PID 1 has ended, reaped or not)."""
    try:
        return proc.status() != psutil.STATUS_ZOMBIE
    except psutil.Error:
        return False
