"""Tab completion in a real bash, through the set-up's hook (argcomplete, as ros2cli)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from tests.support.nodes import script_launched

REPO = Path(__file__).resolve().parents[2]
PY = sys.executable
TALKER = """
from launcher.bus.node import Node
node = Node("chatty")
node.create_publisher("std_msgs/msg/String", "chatter")
node.get_logger().info("up")
node.spin()
node.destroy_node()
"""


def completions(ws, line: str) -> list[str]:
    """What bash offers at the end of `line`, with hooks/setup.bash sourced."""
    script = (f'. "{REPO}/hooks/setup.bash" >/dev/null\n'
              'COMP_LINE="$1"; COMP_POINT=${#COMP_LINE}\n'
              'read -ra COMP_WORDS <<< "$COMP_LINE"\n'
              '[ "${COMP_LINE: -1}" = " " ] && COMP_WORDS+=("")\n'
              'COMP_CWORD=$(( ${#COMP_WORDS[@]} - 1 ))\n'
              'complete -p launcher >&2\n'
              '_python_argcomplete launcher "${COMP_WORDS[COMP_CWORD]}" '
              '"${COMP_WORDS[COMP_CWORD-1]}"\n'
              'printf "%s\\n" "${COMPREPLY[@]}"\n')
    result = subprocess.run(["bash", "-c", script, "bash", line], cwd=ws.root, env=ws.env,
                            capture_output=True, text=True, timeout=60)
    assert "_python_argcomplete launcher" in result.stderr, result.stderr
    return [w.strip() for w in result.stdout.splitlines() if w.strip()]


@pytest.mark.parametrize("line, expected, absent", [
    ("launcher to", ["topic"], []),
    ("launcher topic e", ["echo"], []),
    ("launcher topic echo --qos-d", ["--qos-depth", "--qos-durability"], []),
    ("launcher bag record --max-", ["--max-bag-duration", "--max-bag-size"], []),
    ("launcher param ", ["describe", "delete", "dump", "get"], ["echo"]),
])
def test_commands_verbs_and_options_complete(ws, line, expected, absent):
    offered = completions(ws, line)
    assert all(word in offered for word in expected), offered
    assert not any(word in offered for word in absent), offered


def test_names_on_the_graph_complete(ws):
    ws.own_bus()
    assert completions(ws, "launcher topic echo /") == []  # no graph yet, and a Tab
    assert not (ws.root / "run" / "domain-0.log").exists()  # starts no router for it
    with script_launched(ws, "chatty.py", TALKER, "up"):
        assert "/chatter" in completions(ws, "launcher topic echo /ch")
        assert "/chatty" in completions(ws, "launcher param list /")


def test_zsh_registers_and_completes_with_descriptions(ws, tmp_path):
    """zsh: . hooks/setup.sh registers the completion (compinit's table), and the program
    answers zsh's request (as the registered function asks it) with each word's help."""
    registered = subprocess.run(
        ["zsh", "-c", f'. "{REPO}/hooks/setup.sh" >/dev/null; print -r -- ${{_comps[launcher]}}'],
        cwd=ws.root, env=ws.env, capture_output=True, text=True, timeout=60)
    assert registered.stdout.strip() == "_python_argcomplete", registered.stderr
    out = tmp_path / "answer"
    line = "launcher topic ec"
    subprocess.run(["launcher"], cwd=ws.root, timeout=60, env={
        **ws.env, "PATH": f"{REPO / '.venv' / 'bin'}:{ws.env['PATH']}", "_ARGCOMPLETE": "1",
        "_ARGCOMPLETE_SHELL": "zsh", "_ARGCOMPLETE_SUPPRESS_SPACE": "1", "COMP_LINE": line,
        "COMP_POINT": str(len(line)), "_ARGCOMPLETE_STDOUT_FILENAME": str(out)})
    assert out.read_text() == "echo:print the messages on a topic"
