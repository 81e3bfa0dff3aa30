"""`launcher control view_controller_chains`: draw the controllers and their interfaces
(graphviz)."""

from __future__ import annotations

import argparse
import shutil
import subprocess
from pathlib import Path

from launcher.cli.control.manager import add_manager_option, on_manager
from launcher.errors import LaunchError
from launcher.nodes.spawner import Manager


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_manager_option(parser)


@on_manager
def run(manager: Manager, args: argparse.Namespace) -> int:
    controllers = manager.call("list_controllers").controller
    interfaces = manager.call("list_hardware_interfaces")
    lines = ["digraph controller_diagram {", "  rankdir=LR;",
             "  node [shape=record, fontname=Helvetica];"]
    for c in controllers:
        inputs = "|".join(c.required_state_interfaces) or " "
        outputs = "|".join(c.claimed_interfaces or c.required_command_interfaces) or " "
        lines.append(f'  "{c.name}" [label="{c.name} ({c.state})|{{{{{inputs}}}|'
                     f'{{{outputs}}}}}"];')
    commands = [i.name for i in interfaces.command_interfaces]
    states = [i.name for i in interfaces.state_interfaces]
    lines.append(f'  "command_interfaces" [label="command interfaces|{"|".join(commands)}"];')
    lines.append(f'  "state_interfaces" [label="state interfaces|{"|".join(states)}"];')
    for c in controllers:
        if c.required_state_interfaces:
            lines.append(f'  "state_interfaces" -> "{c.name}";')
        if c.required_command_interfaces:
            lines.append(f'  "{c.name}" -> "command_interfaces";')
    lines.append("}")
    gv = Path("controller_diagram.gv").resolve()
    gv.write_text("\n".join(lines) + "\n")
    dot = shutil.which("dot")
    if dot is None:
        raise LaunchError(f"graphviz's dot is not installed, so {gv} is written but not "
                          f"its PDF: apt-get install graphviz")
    pdf = gv.with_name("controller_diagram.gv.pdf")
    subprocess.run([dot, "-Tpdf", str(gv), "-o", str(pdf)], check=True)
    print(f"Diagram written to {pdf} (graphviz source: {gv})")
    return 0
