"""The ssh command line a launch runs to reach another host, and what each of OpenSSH's
failures is said as (its real stderr, as OpenSSH 9 prints it)."""

from __future__ import annotations

import shlex

import pytest

from launcher.errors import LaunchError
from launcher.runtime import host_link, ssh
from launcher.runtime.machine import Machine

ROBOT2 = Machine("robot2", "10.0.0.2", user="pi", ssh_port=2222, timeout=4.0)


def test_the_users_own_ssh_runs_unless_launcher_ssh_command_names_another():
    assert ssh.argv(ROBOT2, "/c/%C", {})[0] == "ssh"
    assert ssh.argv(ROBOT2, "/c/%C", {ssh.VARIABLE: "ssh -F 'my config'"})[:3] == \
        ["ssh", "-F", "my config"]


def test_no_prompt_is_ever_shown_and_host_keys_are_never_accepted_for_the_user():
    words = ssh.argv(ROBOT2, "/c/%C", {})
    assert "BatchMode=yes" in words
    assert "StrictHostKeyChecking=yes" in words  # (a config file's accept-new loses to it)


def test_one_connection_per_host_is_shared():
    words = ssh.argv(ROBOT2, "/c/%C", {})
    assert "ControlMaster=auto" in words and "ControlPath=/c/%C" in words


def test_port_user_and_timeout_come_from_the_machine():
    words = ssh.argv(ROBOT2, "/c/%C", {})
    assert words[words.index("-p") + 1] == "2222"
    assert words[words.index("-l") + 1] == "pi"
    assert "ConnectTimeout=4" in words
    assert words[-2:-1] == ["10.0.0.2"]


def test_the_remote_command_starts_the_supervisor_through_the_env_loader():
    machine = Machine("robot2", "10.0.0.2", env_loader="/opt/ws/env.sh")
    command = ssh.argv(machine, "/c/%C", {})[-1]
    inner = shlex.split(command)[-1]  # exec /bin/sh -c '<inner>'
    assert "/opt/ws/env.sh /bin/sh -c" in inner
    assert "launcher remote-supervisor" in inner


def test_no_secret_and_no_local_path_is_on_the_remote_command_line():
    command = ssh.argv(ROBOT2, "/c/%C", {"LAUNCHER_CREDENTIALS": "/secret"})[-1]
    assert "/secret" not in command and "/c/" not in command


FAILURES = [
    ("ssh: Could not resolve hostname robot9: Name or service not known", "cannot resolve"),
    ("ssh: connect to host 10.0.0.2 port 2222: Connection refused",
     "refused the connection on port 2222: is sshd running there"),
    ("pi@10.0.0.2: Permission denied (publickey).",
     "logging in as pi@10.0.0.2 failed (publickey)"),
    ("No ED25519 host key is known for [10.0.0.2]:2222 and you have requested strict "
     "checking.\nHost key verification failed.", "is not in your known_hosts"),
    ("@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@\n"
     "@    WARNING: REMOTE HOST IDENTIFICATION HAS CHANGED!     @\n"
     "Offending ED25519 key in /home/pi/.ssh/known_hosts:3\n"
     "Host key verification failed.",
     "does not match known_hosts (/home/pi/.ssh/known_hosts:3)"),
    ("ssh: connect to host 10.0.0.2 port 2222: Connection timed out",
     "did not answer within 4 s"),
    (ssh.NO_LAUNCHER, "launcher is not installed there"),
]


@pytest.mark.parametrize(("stderr", "said"), FAILURES, ids=[s for _, s in FAILURES])
def test_each_failure_of_ssh_is_said_in_words(stderr, said):
    text = ssh.explain(ROBOT2, 255, stderr)
    assert text.startswith("machine 'robot2' (pi@10.0.0.2:2222): ")
    assert said in text


def test_a_failure_no_rule_knows_quotes_what_ssh_said():
    text = ssh.explain(ROBOT2, 255, "kex_exchange_identification: read: Connection reset")
    assert "ssh said: kex_exchange_identification" in text


def test_the_link_timeout_must_be_a_positive_number():
    assert host_link.silence({host_link.SILENCE_VARIABLE: "2"}) == 2.0
    with pytest.raises(LaunchError, match="expected seconds, a number > 0"):
        host_link.silence({host_link.SILENCE_VARIABLE: "soon"})
    with pytest.raises(LaunchError, match="expected seconds"):
        host_link.silence({host_link.SILENCE_VARIABLE: "0"})
