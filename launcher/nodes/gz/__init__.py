"""`gz topic|service|model …`: Gazebo's command line over launcher's sim (`gz sim` is the sim,
which `launcher gz` runs itself: launcher/cli/gz_command.py).

  gz topic -l | -i -t T | -e -t T [-n N] [-d S] [--json-output] | -t T -m TYPE -p TEXT
  gz service -l | -i -s S | -s S --reqtype TYPE --reptype TYPE [--timeout MS] --req TEXT
  gz model --list | -m NAME [-p]
Types are Gazebo's names (gz.msgs.Twist, ignition.msgs.Twist); texts are Protocol Buffers'
text format, and `-e` prints messages in it, as Gazebo does. Unlike Gazebo, `-p` waits
(up to a second) for the topic's subscribers before it publishes, so the one message is
not lost to discovery.
"""

from __future__ import annotations

from launcher.errors import UsageError, did_you_mean
from launcher.nodes.gz.model import model
from launcher.nodes.gz.service import service
from launcher.nodes.gz.topic import topic

VERBS = {"sim": "run a world (launcher's MuJoCo sim)", "topic": "topics of the sim",
         "service": "services of the sim", "model": "models of the running world"}


def usage() -> str:
    lines = ["usage: gz COMMAND [options]  (launcher's Gazebo commands)", "commands:"]
    lines += [f"  {name:<8} {text}" for name, text in VERBS.items()]
    return "\n".join(lines)


def main(argv: list[str]) -> int:
    if not argv or argv[0] in ("-h", "--help", "help"):
        print(usage())
        return 0
    verb, rest = argv[0], argv[1:]
    if verb in ("--version", "--versions"):
        print("launcher's gz (MuJoCo sim)")
        return 0
    commands = {"topic": topic, "service": service, "model": model}
    if verb not in commands:
        raise UsageError(f"gz: unknown command '{verb}'{did_you_mean(verb, list(VERBS))}; "
                      f"commands: {', '.join(VERBS)}")
    return commands[verb](rest)


