"""roslaunch.rlutil: the helpers roslaunch's command and scripts share: the run id, launch
files found from command-line words, and checks of launch files."""

from __future__ import annotations

import os
import sys

from roslaunch.core import RLException, generate_run_id, printerrlog

DEFAULT_MASTER_PORT = 11311


def resolve_launch_arguments(args: list[str]) -> list[str]:
    """Command-line words as roslaunch takes them: [FILE, name:=value …] or
    [PACKAGE, FILE, …] become [the launch file's path, the other words …]."""
    words = [w for w in args if not w.startswith("__")]  # (rosgraph.myargv's)
    if not words:
        return words
    if len(words) >= 2:
        from launcher.packages.index import PackageIndex, PackageNotFound

        try:
            package = PackageIndex.from_environment(os.environ).get(words[0])
        except PackageNotFound:
            package = None
        if package is not None:
            found = sorted(str(p) for p in package.path.rglob(words[1]) if p.is_file())
            if len(found) > 1:
                listed = "".join(f"\n- {f}" for f in found)
                raise RLException(f"multiple files named [{words[1]}] in package "
                                  f"[{words[0]}]:{listed}\nPlease specify full path instead")
            if found:
                return [found[0], *words[2:]]
    if words[0] == "-" or os.path.isfile(words[0]):
        return words
    if len(words) >= 2:
        raise RLException(f"[{words[1]}] is neither a launch file in package [{words[0]}] "
                          f"nor is [{words[0]}] a launch file name")
    raise RLException(f"[{words[0]}] is not a launch file name")


def get_or_generate_uuid(options_runid: str | None, options_wait_for_master: bool) -> str:
    """The run id: `options_runid` when given, else a new one (launcher's graph keeps no
    /run_id for a launch to share: each launch's run has its own)."""
    return options_runid or generate_run_id()


def check_roslaunch(f: str, use_test_depends: bool = False,
                    ignore_unset_args: bool = False) -> str | None:
    """Why launch file `f` cannot be loaded (None when it can): launcher's reading of it,
    arguments, includes and substitutions resolved."""
    from roslaunch.config import load_config_default

    try:
        load_config_default([f], DEFAULT_MASTER_PORT, verbose=False,
                            ignore_unset_args=ignore_unset_args)
    except RLException as exc:
        return str(exc)
    return None


def print_file_list(roslaunch_files: list[str]) -> None:
    """Print the files the launch reads (the files and those they include)."""
    from roslaunch.node_args import loaded

    try:
        print("\n".join(str(f) for f in loaded(roslaunch_files).files))
    except RLException as exc:
        printerrlog(str(exc))
        sys.exit(1)


def change_terminal_name(args: list[str], is_core: bool) -> None:
    """Title the terminal after the launch (roscore, or the files)."""
    update_terminal_name("roscore" if is_core else ",".join(args))


def update_terminal_name(ros_master_uri: str) -> None:
    """Set the terminal's title to `ros_master_uri`, on a terminal."""
    if sys.stdout.isatty():
        sys.stdout.write(f"\033]2;{ros_master_uri}\007")


def check_log_disk_usage() -> None:
    """roslaunch's check of the log folder's size: launcher's logs are its runs' own, kept
    below its log root, and it does not warn here."""
