"""`gz service -l | -i -s S | -s S --reqtype TYPE --reptype TYPE [--timeout MS] --req TEXT`."""

from __future__ import annotations

from typing import Any

from launcher.arguments import Parser
from launcher.bus import graph, keys
from launcher.bus.messages import MessageError, build, to_data
from launcher.bus.node import Node
from launcher.bus.session import open_session
from launcher.errors import LaunchError, UsageError
from launcher.nodes.conversions import gz_short_name, sim_type
from launcher.nodes.gz.common import print_names
from launcher.sim import gz_msgs, prototext


def build_parser() -> Parser:
    """`gz service`'s command line."""
    parser = Parser(prog="gz service", description="Gazebo's services of launcher's sim.",
                     allow_abbrev=False)
    parser.add_argument("-l", "--list", action="store_true", help="list the sim's services")
    parser.add_argument("-i", "--info", action="store_true", help="the service's types")
    parser.add_argument("-s", "--service", metavar="SERVICE", help="the service (-i, --req)")
    parser.add_argument("--reqtype", metavar="TYPE", help="e.g. gz.msgs.WorldControl")
    parser.add_argument("--reptype", metavar="TYPE", help="e.g. gz.msgs.Boolean")
    parser.add_argument("--timeout", type=float, default=1000.0, metavar="MS",
                        help="how long to wait for the answer, in milliseconds")
    parser.add_argument("--req", metavar="TEXT", help="the request, in text format")
    return parser


def service(argv: list[str]) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if args.list:
        return _service_list()
    if not args.service:
        parser.error("-s SERVICE is required with -i and --req")
    if args.info:
        return _service_info(args.service)
    if not (args.reqtype and args.reptype and args.req is not None):
        parser.error("a call needs --reqtype, --reptype and --req")
    return _call(args.service, args.reqtype, args.reptype, args.req, args.timeout / 1000.0)


def _services(session: Any) -> list[keys.Entity]:
    return [e for e in graph.entities(session, space=keys.SIM) if e.kind == keys.SERVICE]


def _service_list() -> int:
    return print_names(lambda session: {e.topic for e in _services(session)})


def _service_info(name: str) -> int:
    session = open_session("client")
    try:
        found = [e for e in _services(session) if e.topic == name]
    finally:
        session.close()
    if not found:
        raise LaunchError(f"no service [{name}] on the sim")
    print("Service providers [Node, Service Type]:")
    for entity in found:
        print(f"  {entity.node_fqn}, {entity.type_name}")
    return 0


def _call(name: str, reqtype: str, reptype: str, text: str, timeout: float) -> int:
    try:
        service_type = sim_type(f"{reqtype}|{reptype}")
    except LaunchError as exc:
        raise UsageError(exc.message) from None
    request_short = gz_short_name(reqtype)
    data = gz_msgs.to_sim(request_short, prototext.parse(text, "--req"))
    node = Node("_launcher_gz_service", argv=[], parameter_services=False, space=keys.SIM)
    try:
        client = node.create_client(service_type, name)
        try:
            request = build(client.request_type, data)
        except MessageError as exc:
            raise UsageError(f"--req: '{text}' does not fit {reqtype}: "
                          f"{exc.message.replace(client.request_type, reqtype)}") from None
        if not client.wait_for_service(max(timeout, 0.5)):
            raise LaunchError(f"service [{name}] ({reqtype} -> {reptype}) is not offered "
                              "(`gz service -l` lists the sim's services)")
        response = client.call(request, max(timeout, 0.1))
    finally:
        node.destroy_node()
    reply = to_data(response)
    print(prototext.format(gz_msgs.reply_to_gz(gz_short_name(reptype), reply)) or "data: false\n")
    if not reply.get("success", True):
        raise LaunchError(f"the sim refused: {reply.get('message', '')}")
    return 0


