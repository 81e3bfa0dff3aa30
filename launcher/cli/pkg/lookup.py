"""Where a package is: its prefix, its share folder, its package.xml."""

from __future__ import annotations

import argparse
import sys

from launcher.cli.workspace import load_index


def lookup(args: argparse.Namespace, verb: str) -> int:
    index = load_index()
    if verb == "share":
        print(index.share(args.package))
    elif verb == "prefix":
        print(index.prefix(args.package))
    else:
        sys.stdout.write(index.get(args.package).manifest.read_text())
    return 0
