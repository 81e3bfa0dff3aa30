"""`view_frames`: listens to /tf and /tf_static for a while (5 s, `--wait-time`), then writes
the tf tree as graphviz's `frames_<date>.gv` and, with graphviz's `dot`, `frames_<date>.pdf`,
as tf2_tools' view_frames does, and says where. Without `dot` (Debian's graphviz package) the
.gv is written and the error says how to get the PDF."""

from __future__ import annotations

import argparse
import shutil
import subprocess
import sys
import time
from pathlib import Path

from launcher.bus.node import Node
from launcher.bus.tf_tree import BufferCore
from launcher.errors import LaunchError, reported
from launcher.nodes.tf_feed import feed


def graph(tree: BufferCore, recorded: float) -> str:
    """The tree as tf2_tools writes it: an edge per frame, labelled with its broadcaster,
    rate, buffer length and newest and oldest transforms."""
    lines = ["digraph G {"]
    roots = set()
    edges = tree.edges()
    children = {edge.name for edge in edges}
    for edge in edges:
        name, parent = edge.name, edge.parent
        newest = 0.0 if edge.static else edge.newest / 1e9
        oldest = 0.0 if edge.static else edge.oldest / 1e9
        span = newest - oldest
        rate = (edge.count - 1) / span if span > 0 else 10000.0
        lines.append(f'"{parent}" -> "{name}"[label=" Broadcaster: {edge.authority}\\n'
                     f"Average rate: {rate:.3f}\\nBuffer length: {span:.3f}\\n"
                     f"Most recent transform: {newest:.3f}\\nOldest transform: {oldest:.3f}\\n"
                     '"];')
        if parent not in children:
            roots.add(parent)
    lines.append("edge [style=invis];")
    lines.append(' subgraph cluster_legend { style=bold; color=black; label ="view_frames '
                 'Result";')
    lines.append(f'"Recorded at time: {recorded:.3f}"[ shape=plaintext ] ;')
    lines.append("}" + "".join(f'->"{root}"' for root in sorted(roots)) + ";")
    lines.append("}")
    return "\n".join(lines) + "\n"


def run(argv: list[str]) -> int:
    node = Node("view_frames", argv=argv)
    try:
        parser = argparse.ArgumentParser(prog="view_frames")
        parser.add_argument("--wait-time", "-t", type=float, default=5.0,
                            help="seconds to listen to tf (5)")
        args = parser.parse_args(list(node.args))
        tree = BufferCore()

        feed(node, tree, "default_authority")
        logger = node.get_logger()
        logger.info(f"Listening to tf data for {args.wait_time} seconds...")
        node.spin(args.wait_time)
        name = time.strftime("frames_%Y-%m-%d_%H.%M.%S")
        dot_file, pdf = Path(f"{name}.gv"), Path(f"{name}.pdf")
        dot_file.write_text(graph(tree, time.time()))
        logger.info(f"Generating graph in {pdf} file...")
        logger.info(f"Result:{tree.as_yaml()}" if tree.frames() else
                    "Result: no transforms were heard on /tf or /tf_static")
        dot = shutil.which("dot")
        if dot is None:
            raise LaunchError(f"graphviz's dot is not installed, so {dot_file} is written but "
                              f"not {pdf}: apt-get install graphviz, then dot -Tpdf "
                              f"{dot_file} -o {pdf}")
        subprocess.run([dot, "-Tpdf", str(dot_file), "-o", str(pdf)], check=True)
    finally:
        node.destroy_node()
    return 0


def main() -> int:
    return reported(lambda: run(sys.argv[1:]), "view_frames")


if __name__ == "__main__":
    sys.exit(main())
