"""xacro in the launcher's own process, for `$(command 'xacro FILE name:=value …')`.

Same library, same argument parser, same output as the `xacro` command (a file written with
-o, or --deps, still go to the command); it saves starting a Python process per robot.
`$(find pkg)` inside the file resolves through launcher's package index.
"""

from __future__ import annotations

import io
import os
import shutil
import sys
from collections.abc import Iterator, Mapping
from contextlib import contextmanager, redirect_stderr
from typing import Any

from launcher.errors import ExecutionError

BUILTIN_XACRO = os.path.realpath(os.path.join(os.path.dirname(__file__), os.pardir, "builtin",
                                              "xacro", "xacro"))


def runs_in_process(argv: list[str], environment: Mapping[str, str]) -> bool:
    """True when `argv` is a xacro call this process can do with identical results."""
    if not argv or os.path.basename(argv[0]) != "xacro":
        return False
    if os.path.realpath(argv[0]) == BUILTIN_XACRO:  # ROS 1's `$(find xacro)/xacro`
        return True
    on_path = shutil.which(argv[0], path=environment.get("PATH", os.defpath))
    ours = os.path.join(sys.prefix, "bin", "xacro")
    return on_path is None or os.path.realpath(on_path) == os.path.realpath(ours)


@contextmanager
def finding_in(index: Any) -> Iterator[None]:
    """xacro's `$(find pkg)` (and `find()` in its expressions) answered from launcher's package
    index, for this call only: no ament_index_python needed in this process, nothing global
    left behind."""
    from xacro import substitution_args

    def find(package: str) -> str:
        return str(index.share(package))

    saved = substitution_args._eval_find, substitution_args._eval_dict["find"]
    substitution_args._eval_find = substitution_args._eval_dict["find"] = find
    try:
        yield
    finally:
        substitution_args._eval_find, substitution_args._eval_dict["find"] = saved


def run_xacro(argv: list[str], index: Any) -> str | None:
    """The xacro output, or None if these options need the real command."""
    import xacro  # only when a xacro command runs: start-up time
    from xacro.cli import process_args

    try:
        with redirect_stderr(io.StringIO()):
            options, input_file = process_args(argv[1:])
    except SystemExit:
        return None  # let the command report its own usage error
    if options.output or options.just_deps:
        return None
    try:
        with finding_in(index):
            doc = xacro.process_file(input_file, **vars(options))
    except Exception as exc:  # xacro raises plain exceptions with good messages
        files = " (included from ".join(str(f) for f in reversed(xacro.filestack or []) if f)
        where = f"\n  in {files}{')' * (files.count('(included'))}" if files else ""
        message = str(exc) or repr(exc)
        raise ExecutionError(f"xacro failed: {message}{where}") from None
    return doc.toprettyxml(indent="  ")
