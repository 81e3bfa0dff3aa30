"""rosbag.rosbag_main: the `rosbag` command's Python side. info, filter, compress, decompress,
check and fix work on bags here; record and play need a running graph, which launcher's own
`launcher rosbag record|play` reach; reindex, encrypt and decrypt say why they cannot run
(rosbags reads neither unindexed nor encrypted bags)."""

from __future__ import annotations

import optparse
import os
import shutil
import sys
import time
from collections import UserDict
from typing import Any

from rosbag.bag import (  # noqa: F401
    Bag,
    Compression,
    ROSBagEncryptException,
    ROSBagEncryptNotSupportedException,
    ROSBagException,
    ROSBagFormatException,
    ROSBagUnindexedException,
)
from rosbag.migration import MessageMigrator, checkbag, fixbag2


def print_trans(old: Any, new: Any, indent: int) -> None:
    """Print one migration step: the old type and md5sum, and the new one."""
    def text(c: Any) -> str:
        return "Unknown" if c is None else f"{getattr(c, '_type', c)} [{getattr(c, '_md5sum', '')}]"

    from_text, to_text = text(old), text(new)
    print("    " * indent + f" * From: {from_text}\n" + "    " * indent + f"   To:   {to_text}")


def handle_split(option: Any, opt_str: str, value: Any, parser: Any) -> None:
    """optparse callback of record's --split [--size|--duration]."""
    parser.values.split = True
    if parser.rargs and not parser.rargs[0].startswith("-"):
        parser.values.chunk_threshold = int(parser.rargs.pop(0))


def handle_topics(option: Any, opt_str: str, value: Any, parser: Any) -> None:
    """optparse callback of play's --topics: every word after it that is not an option."""
    topics = []
    while parser.rargs and not parser.rargs[0].startswith("-"):
        topics.append(parser.rargs.pop(0))
    parser.values.topics = topics


def handle_pause_topics(option: Any, opt_str: str, value: Any, parser: Any) -> None:
    """optparse callback of play's --pause-topics."""
    topics = []
    while parser.rargs and not parser.rargs[0].startswith("-"):
        topics.append(parser.rargs.pop(0))
    parser.values.pause_topics = topics


def _on_graph(verb: str) -> None:
    print(f"rosbag {verb} needs launcher's graph: run `launcher rosbag {verb}` (same options)",
          file=sys.stderr)
    raise SystemExit(1)


def record_cmd(argv: list[str]) -> None:
    """`rosbag record`: launcher's `launcher rosbag record` records on its graph."""
    _on_graph("record")


def play_cmd(argv: list[str]) -> None:
    """`rosbag play`: launcher's `launcher rosbag play` plays on its graph."""
    _on_graph("play")


def info_cmd(argv: list[str]) -> None:
    """`rosbag info BAG…`: each bag's summary."""
    parser = optparse.OptionParser(usage="rosbag info [options] BAGFILE1 [BAGFILE2 ...]")
    parser.add_option("-y", "--yaml", action="store_true", help="(not supported: plain text)")
    parser.add_option("-k", "--key", help="(not supported)")
    parser.add_option("--freq", action="store_true", help="(frequencies are always shown)")
    _, args = parser.parse_args(argv)
    if not args:
        parser.error("You must specify at least 1 bag file.")
    for number, name in enumerate(args):
        try:
            with Bag(name, "r") as bag:
                print(bag)
        except (ROSBagException, OSError) as exc:
            print(f"ERROR reading {name}: {exc}", file=sys.stderr)
        if number < len(args) - 1:
            print("---")


def filter_cmd(argv: list[str]) -> None:
    """`rosbag filter INBAG OUTBAG EXPRESSION`: the messages for which the Python expression
    (of topic, m, t) is true."""
    parser = optparse.OptionParser(usage="rosbag filter [options] INBAG OUTBAG EXPRESSION")
    parser.add_option("-p", "--print", dest="verbose_pattern", default=None)
    options, args = parser.parse_args(argv)
    if len(args) != 3:
        parser.error("You must specify an in bag, an out bag, and an expression.")
    inbag, outbag, expression = args
    if os.path.realpath(inbag) == os.path.realpath(outbag):
        parser.error(f"Cannot use same file as input and output [{inbag}]")
    keep = eval(f"lambda topic, m, t: {expression}")  # noqa: S307 (rosbag's documented use)
    with Bag(inbag) as source, Bag(outbag, "w") as target:
        for topic, msg, t, header in source.read_messages(return_connection_header=True):
            if keep(topic, msg, t):
                target.write(topic, msg, t, connection_header=header)


def _migration_cmd(argv: list[str], verb: str) -> None:
    parser = optparse.OptionParser(usage=f"rosbag {verb} [options] INBAG" +
                                   (" OUTBAG [RULEFILE…]" if verb == "fix" else ""))
    parser.add_option("-n", "--noplugins", action="store_true")
    parser.add_option("--force", action="store_true")
    options, args = parser.parse_args(argv)
    if len(args) < (2 if verb == "fix" else 1):
        parser.error("You must specify the bag(s).")
    migrator = MessageMigrator(args[2:] if verb == "fix" else [], not options.noplugins)
    missing = fixbag2(migrator, args[0], args[1], options.force) if verb == "fix" \
        else checkbag(migrator, args[0])
    if not missing:
        print(f"Bag migrated successfully into {args[1]}." if verb == "fix" else
              "Bag file does not need any migrations.")
        return
    print("The following types differ from launcher's and no rules migrate them:",
          file=sys.stderr)
    for raw, _rules in missing:
        print(f"  {raw[0]} [{raw[2]}]", file=sys.stderr)
    raise SystemExit(1)


def check_cmd(argv: list[str]) -> None:
    """`rosbag check BAG`: whether every stored type is launcher's as it is."""
    _migration_cmd(argv, "check")


def fix_cmd(argv: list[str]) -> None:
    """`rosbag fix INBAG OUTBAG`: copy a bag that needs no migration."""
    _migration_cmd(argv, "fix")


def _compression_cmd(argv: list[str], compression: str, verb: str) -> None:
    parser = optparse.OptionParser(usage=f"rosbag {verb} [options] BAGFILE1 [BAGFILE2 ...]")
    parser.add_option("--output-dir", metavar="DIR")
    parser.add_option("-f", "--force", action="store_true")
    parser.add_option("-q", "--quiet", action="store_true")
    options, args = parser.parse_args(argv)
    if not args:
        parser.error("You must specify at least one bag file.")
    bag_op(args, False, True, lambda bag: False,
           lambda inbag, outbag, quiet: change_compression_op(inbag, outbag, compression,
                                                              quiet),
           options.output_dir, options.force, options.quiet)


def compress_cmd(argv: list[str]) -> None:
    """`rosbag compress [--lz4] BAG…`: rewrite bags compressed (bz2, or lz4)."""
    lz4 = "--lz4" in argv
    _compression_cmd([a for a in argv if a not in ("--lz4", "--bz2", "-j")],
                     Compression.LZ4 if lz4 else Compression.BZ2, "compress")


def decompress_cmd(argv: list[str]) -> None:
    """`rosbag decompress BAG…`: rewrite bags uncompressed."""
    _compression_cmd(argv, Compression.NONE, "decompress")


def reindex_cmd(argv: list[str]) -> None:
    """`rosbag reindex`: not supported (rosbags reads indexed bags only)."""
    print("rosbag reindex is not supported by launcher's rosbag: rosbags reads indexed bags "
          "only", file=sys.stderr)
    raise SystemExit(1)


def encrypt_cmd(argv: list[str]) -> None:
    """`rosbag encrypt`: not supported (rosbags writes no encrypted bags)."""
    raise ROSBagEncryptNotSupportedException("launcher's rosbag writes no encrypted bags")


def decrypt_cmd(argv: list[str]) -> None:
    """`rosbag decrypt`: not supported (rosbags reads no encrypted bags)."""
    raise ROSBagEncryptNotSupportedException("launcher's rosbag reads no encrypted bags")


def bag_op(inbag_filenames: list[str], allow_unindexed: bool, open_inbag: bool, copy_fn: Any,
           op: Any, output_dir: str | None = None, force: bool = False,
           quiet: bool = False) -> None:
    """Run `op(inbag, outbag, quiet)` on each bag; written in place, the original is kept as
    NAME.orig.bag."""
    for name in inbag_filenames:
        if open_inbag:
            try:
                with Bag(name, "r", allow_unindexed=allow_unindexed):
                    pass
            except (ROSBagException, OSError) as exc:
                print(f"ERROR reading {name}: {exc}", file=sys.stderr)
                continue
        outbag = name if output_dir is None else os.path.join(output_dir,
                                                              os.path.basename(name))
        source = name
        if outbag == name:
            stem, suffix = os.path.splitext(name)
            source = f"{stem}.orig{suffix}"
            if not force and os.path.exists(source):
                if not quiet:
                    print(f"Skipping {name}. Backup path {source} already exists.",
                          file=sys.stderr)
                continue
            shutil.move(name, source)
        with Bag(source) as inbag, Bag(outbag, "w") as written:
            op(inbag, written, quiet)


def change_compression_op(inbag: Bag, outbag: Bag, compression: str, quiet: bool) -> None:
    """Copy every message of `inbag` into `outbag`, compressed so."""
    outbag.compression = compression
    for topic, raw, t, header in inbag.read_messages(raw=True, return_connection_header=True):
        outbag.write(topic, raw, t, raw=True, connection_header=header)


def reindex_op(inbag: Bag, outbag: Bag, quiet: bool) -> None:
    """Rebuild an index: not supported (see Bag.reindex)."""
    inbag.reindex()


def change_encryption_op(inbag: Bag, outbag: Bag, plugin: str, param: Any, compression: str,
                         quiet: bool) -> None:
    """Encrypt or decrypt: not supported (see Bag.set_encryptor)."""
    outbag.set_encryptor(plugin, param)


class RosbagCmds(UserDict):  # type: ignore[type-arg]
    """The subcommands: name → function of argv, with their descriptions."""

    def __init__(self) -> None:
        super().__init__()
        self.descriptions: dict[str, str] = {}
        self["help"] = self.help_cmd

    def add_cmd(self, name: str, function: Any, description: str) -> None:
        """Add a subcommand."""
        self[name] = function
        self.descriptions[name] = description

    def get_valid_cmds(self) -> str:
        """The list of subcommands, as help prints it."""
        return "Available subcommands:\n" + "".join(
            f"   {name}  " + (f"\t{self.descriptions[name]}" if name in self.descriptions
                              else "") + "\n" for name in sorted(self))

    def help_cmd(self, argv: list[str]) -> None:
        """Print the usage, or a subcommand's help."""
        argv = [a for a in argv if a not in ("-h", "--help")]
        if not argv:
            print("Usage: rosbag <subcommand> [options] [args]\n")
            print(self.get_valid_cmds())
        elif argv[0] in self:
            self[argv[0]](["-h"])
        else:
            print(f"Unknown command: '{argv[0]}'", file=sys.stderr)
            print(self.get_valid_cmds(), file=sys.stderr)


class ProgressMeter:
    """A one-line progress display of bytes done out of a total."""

    def __init__(self, path: str, bytes_total: int, refresh_rate: float = 1.0) -> None:
        self.path, self.bytes_total, self.refresh_rate = path, bytes_total, refresh_rate
        self.elapsed = self.update_elapsed = self.bytes_read = 0.0
        self.start_time = time.time()

    def step(self, bytes_read: float, force_update: bool = False) -> None:
        """Record progress, shown at most once per refresh_rate seconds."""
        self.bytes_read, self.elapsed = bytes_read, time.time() - self.start_time
        if force_update or self.elapsed - self.update_elapsed > self.refresh_rate:
            share = 100 * self.bytes_read / self.bytes_total if self.bytes_total else 100
            print(f"\r {self.path[-(self.terminal_width() - 37):]} {share:3.0f}%", end="")
            sys.stdout.flush()
            self.update_elapsed = self.elapsed

    def finish(self) -> None:
        """Show completion and end the line."""
        self.step(self.bytes_total, force_update=True)
        print()

    @staticmethod
    def terminal_width() -> int:
        """The terminal's width (80 when unknown)."""
        return shutil.get_terminal_size((80, 24)).columns


_COMMANDS = (
    ("record", record_cmd, "Record a bag file with the contents of specified topics."),
    ("info", info_cmd, "Summarize the contents of one or more bag files."),
    ("play", play_cmd, "Play back the contents of one or more bag files."),
    ("check", check_cmd, "Determine whether a bag is playable in the current system."),
    ("fix", fix_cmd, "Repair the messages in a bag file so that it can be played."),
    ("filter", filter_cmd, "Filter the contents of the bag."),
    ("compress", compress_cmd, "Compress one or more bag files."),
    ("decompress", decompress_cmd, "Decompress one or more bag files."),
    ("reindex", reindex_cmd, "Reindexes one or more bag files."),
    ("encrypt", encrypt_cmd, "Encrypt one or more bag files."),
    ("decrypt", decrypt_cmd, "Decrypt one or more bag files."),
)


def rosbagmain(argv: list[str] | None = None) -> None:
    """The `rosbag` command: argv as sys.argv (the program's name first)."""
    commands = RosbagCmds()
    for name, function, description in _COMMANDS:
        commands.add_cmd(name, function, description)
    argv = list(sys.argv if argv is None else argv)
    if "-h" in argv or "--help" in argv:
        argv = [a for a in argv if a not in ("-h", "--help")]
        argv.insert(1, "help")
    command = argv[1] if len(argv) > 1 else "help"
    try:
        if command in commands:
            commands[command](argv[2:])
        else:
            commands["help"]([command])
    except KeyboardInterrupt:
        pass
