"""`launcher graph [-o graph.png]`: the graph as rqt_graph draws it, with graphviz: each node
an ellipse, each topic a box, an arrow from a publisher to its topic and from the topic to each
subscriber; written to a file whose extension says the format (png, svg, pdf, or gv for
graphviz's text). The launcher's own tools, parameter services and /rosout are left out unless
`--all`."""

from __future__ import annotations

import argparse
import shutil
import subprocess
from pathlib import Path

from launcher.bus import graph, keys
from launcher.bus.session import open_session
from launcher.cli.graph_options import add_sim_option
from launcher.errors import LaunchError, UsageError

FORMATS = ("png", "svg", "pdf", "gv")
HIDDEN_TOPICS = ("/rosout", "/parameter_events")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-o", "--output", default="graph.png",
                        help="the picture to write: .png (default graph.png), .svg, .pdf or .gv")
    parser.add_argument("--all", action="store_true",
                        help="also launcher's own tools, hidden topics and /rosout")
    add_sim_option(parser, "topics")


def dot_text(entities: list[keys.Entity], everything: bool) -> str:
    def shown_node(entity: keys.Entity) -> bool:
        return everything or not entity.node.startswith("_")

    def shown_topic(topic: str) -> bool:
        return everything or (topic not in HIDDEN_TOPICS and
                              not any(part.startswith("_") for part in topic.split("/")))
    nodes = sorted({e.node_fqn for e in entities if e.kind == keys.NODE and shown_node(e)})
    edges, topics = set(), set()
    for e in entities:
        if e.kind not in (keys.PUBLISHER, keys.SUBSCRIPTION) or not shown_node(e) or \
                not shown_topic(e.topic):
            continue
        topics.add(e.topic)
        edges.add((e.node_fqn, e.topic) if e.kind == keys.PUBLISHER else (e.topic, e.node_fqn))
    lines = ["digraph rosgraph {", "  rankdir=LR;"]
    lines += [f'  "n:{n}" [label="{n}", shape=ellipse];' for n in nodes]
    lines += [f'  "t:{t}" [label="{t}", shape=box];' for t in sorted(topics)]
    for start, end in sorted(edges):
        first = f"t:{start}" if start in topics else f"n:{start}"
        second = f"t:{end}" if end in topics else f"n:{end}"
        lines.append(f'  "{first}" -> "{second}";')
    lines.append("}")
    return "\n".join(lines) + "\n"


def run(args: argparse.Namespace) -> int:
    output = Path(args.output)
    kind = output.suffix.lstrip(".").lower()
    if kind not in FORMATS:
        raise UsageError(f"cannot draw into '{output}': give a file ending in "
                         f"{', '.join('.' + f for f in FORMATS)}")
    session = open_session("client")
    try:
        entities = graph.entities(session, space=keys.SIM if args.sim else keys.ROS)
    finally:
        session.close()
    text = dot_text(entities, args.all)
    if kind == "gv":
        output.write_text(text)
        print(f"wrote {output}")
        return 0
    dot = shutil.which("dot")
    if dot is None:
        written = output.with_suffix(".gv")
        written.write_text(text)
        raise LaunchError(f"graphviz's dot is not installed, so {written} is written but not "
                          f"{output}: apt-get install graphviz")
    done = subprocess.run([dot, f"-T{kind}", "-o", str(output)], input=text, text=True,
                          capture_output=True)
    if done.returncode != 0:
        raise LaunchError(f"graphviz's dot could not draw {output}: {done.stderr.strip()}")
    print(f"wrote {output}")
    return 0
