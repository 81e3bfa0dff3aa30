"""`ros2 VERB …` as ROS 2 users type it: each verb is launcher's command of the same name
(their flags and output already follow ros2cli's), `wtf` is `doctor` as in ROS 2, and
`daemon start|stop|status` print what ROS 2 prints and succeed: launcher's graph is answered
by its router, with no daemon to start. A verb of ROS 2 that launcher has no capability for
says so, naming it; a word that is no verb is an error with the list and "did you mean".

The shell reaches this through launcher's `ros2` (compat/bin), which the setup file puts last
on PATH: a real ROS 2's `ros2` earlier on PATH is the one that runs.
"""

from __future__ import annotations

import sys

from launcher.cli.commands import LAUNCHER
from launcher.errors import LaunchError, UsageError, did_you_mean

# ros2cli's verbs and their descriptions, as `ros2 -h` lists them
VERBS = {
    "action": "Various action related sub-commands",
    "bag": "Various rosbag related sub-commands",
    "component": "Various component related sub-commands",
    "control": "Various control related sub-commands",
    "daemon": "Various daemon related sub-commands",
    "doctor": "Check ROS setup and other potential issues",
    "interface": "Show information about ROS interfaces",
    "launch": "Run a launch file",
    "lifecycle": "Various lifecycle related sub-commands",
    "multicast": "Various multicast related sub-commands",
    "node": "Various node related sub-commands",
    "param": "Various param related sub-commands",
    "pkg": "Various package related sub-commands",
    "run": "Run a package specific executable",
    "security": "Various security related sub-commands",
    "service": "Various service related sub-commands",
    "test": "Run a ROS2 launch test",
    "topic": "Various topic related sub-commands",
    "wtf": "Use `wtf` as alias to `doctor`",
}
SAME = {verb for verb in VERBS if verb in LAUNCHER}  # ros2's verbs that are launcher's commands
ALIASES = {"wtf": "doctor"}
MISSING = {  # ROS 2 verbs with no capability in launcher, and why
    "component": "its verbs (list, load, unload, types) are not in launcher yet; the "
                 "containers are: a launch file's node_container and load_composable_node, "
                 "or `launcher service call /CONTAINER/_container/load_node`",
    "multicast": "launcher's graph never uses multicast (it stays on this machine unless "
                 "configured): there is nothing to send or receive",
    "security": "SROS2 keystores are not available in launcher: its graph is private to "
                "your user (a socket only you can open)",
}
DAEMON = {  # what ros2cli's daemon verbs print when all is well
    "start": "The daemon has been started",
    "stop": "The daemon has been stopped",
    "status": "The daemon is running",
}
PROLOGUE = ("usage: ros2 [-h] Call `ros2 <command> -h` for more detailed usage. ...\n\n"
            "ros2 is an extensible command-line tool for ROS 2 (launcher's).\n\n"
            "options:\n  -h, --help            show this help message and exit\n\n"
            "Commands:\n")


def usage() -> str:
    width = max(map(len, VERBS))
    lines = [f"  {verb:<{width}}  {text}" for verb, text in VERBS.items()]
    return PROLOGUE + "\n".join(lines) + "\n\n  Call `ros2 <command> -h` for more detailed " \
        "usage.\n"


# ros2cli's options that ask for what launcher's graph does anyway: the daemon (there is
# none: the router answers), its spin time (the graph's answer is complete at once), hidden
# actions and nodes (launcher's lists show them), doctor's report flavours (its checks are
# its report); taken and dropped, as flag → number of values after it
IMPLIED = {"--no-daemon": 0, "--spin-time": 1, "--include-hidden-actions": 0,
           "--include-hidden-nodes": 0}
DOCTOR_IMPLIED = {"-r": 0, "--report": 0, "-rf": 0, "--report-failed": 0,
                  "-iw": 0, "--include-warnings": 0}


def _without_implied(words: list[str], implied: dict[str, int]) -> list[str]:
    kept: list[str] = []
    skip = 0
    for word in words:
        if skip:
            skip -= 1
        elif word.split("=", 1)[0] in implied:
            skip = 0 if "=" in word else implied[word]
        else:
            kept.append(word)
    return kept


def translate(argv: list[str]) -> list[str] | None:
    """launcher's argv for `ros2 argv…`, or None when this answered by itself (help,
    daemon)."""
    if not argv or argv[0] in ("-h", "--help"):
        sys.stdout.write(usage())
        return None
    verb, rest = argv[0], _without_implied(argv[1:], IMPLIED)
    if verb in ("doctor", "wtf"):
        rest = _without_implied(rest, DOCTOR_IMPLIED)
    if verb == "--use-python-default-buffering":
        return translate(rest)
    if verb in SAME:
        if verb == "pkg" and rest[:1] == ["list"]:  # ros2 lists the names alone
            return [verb, "list", "--names", *rest[1:]]
        return [verb, *rest]
    if verb in ALIASES:
        return [ALIASES[verb], *rest]
    if verb == "daemon":
        return _daemon(rest)
    if verb in MISSING:
        raise LaunchError(f"ros2 {verb}: {MISSING[verb]}")
    raise UsageError(f"ros2: '{verb}' is not a ros2 command{did_you_mean(verb, VERBS)}; the "
                     f"commands: {', '.join(VERBS)}")


def _daemon(rest: list[str]) -> None:
    if not rest or rest[0] in ("-h", "--help"):
        sys.stdout.write("usage: ros2 daemon [-h] Call `ros2 daemon <command> -h` for more "
                         "detailed usage. ...\n\nVarious daemon related sub-commands "
                         "(launcher's graph needs no daemon: these succeed)\n\nCommands:\n"
                         "  start   Start the daemon if it isn't running\n"
                         "  status  Output the status of the daemon\n"
                         "  stop    Stop the daemon if it is running\n")
        return None
    if rest[0] not in DAEMON:
        raise UsageError(f"ros2 daemon: '{rest[0]}' is not a daemon command"
                         f"{did_you_mean(rest[0], DAEMON)}; the commands: start, status, stop")
    print(DAEMON[rest[0]])
    return None


def main(argv: list[str], prog: str = "ros2") -> int:
    """`ros2 argv…`: launcher's command of the verb, or what ros2 prints by itself."""
    translated = translate(argv)
    if translated is None:
        return 0
    from launcher.cli.main import main as launcher_main

    return launcher_main(translated, "ros2")
