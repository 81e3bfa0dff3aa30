"""`catkin build | init | clean` (catkin_tools' verbs users type): `build` is catkin_make's
work (packages/catkin.py) with catkin_tools' devel layout of setup files; `init` marks the
workspace; `clean` removes build/ and devel/."""

from __future__ import annotations

import shutil
from pathlib import Path

from launcher.arguments import Parser


def main(argv: list[str], prog: str = "catkin") -> int:
    p = Parser(prog=prog, description="catkin_tools' verbs for launcher's catkin workspaces")
    verbs = p.add_subparsers(dest="verb", metavar="VERB", required=True)
    build = verbs.add_parser("build", help="build the workspace's packages (catkin_make's work)")
    build.add_argument("packages", nargs="*", help="only these packages")
    build.add_argument("-w", "--workspace", default=".", help="the workspace (default: here)")
    for name in ("init", "clean"):
        verb = verbs.add_parser(name, help="mark the workspace" if name == "init"
                                else "remove build/ and devel/")
        verb.add_argument("-w", "--workspace", default=".", help="the workspace")
    args, _rest = p.parse_known_args(argv)
    workspace = Path(args.workspace).resolve()
    if args.verb == "init":
        (workspace / ".catkin_tools").mkdir(exist_ok=True)
        print(f"Initialized new catkin workspace in `{workspace}`")
        return 0
    if args.verb == "clean":
        for name in ("build", "devel"):
            shutil.rmtree(workspace / name, ignore_errors=True)
        print(f"[clean] Removed build/ and devel/ of {workspace}")
        return 0
    from launcher.cli.ros1 import catkin_make

    return catkin_make.main(["-C", str(workspace),
                             *(["--pkg", *args.packages] if args.packages else [])], "catkin")
