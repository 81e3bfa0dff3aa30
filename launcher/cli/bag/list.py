"""`launcher bag list`: the storage formats (or converters, compressors) bags can use."""

from __future__ import annotations

import argparse

from launcher.bus import bag


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("plugin", nargs="?", default="storage",
                        choices=("storage", "converter", "compressor"),
                        help="which kind of plugin to list (default storage)")


def run(args: argparse.Namespace) -> int:
    """As `ros2 bag list PLUGIN`."""
    names = {"storage": sorted(bag.STORAGES), "converter": ["cdr"], "compressor": ["zstd"]}
    print("\n".join(names[args.plugin]))
    return 0
