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
from collections.abc import Mapping
from contextlib import redirect_stderr
from typing import Any

import launcher.compat
from launcher.errors import ExecutionError


def runs_in_process(argv: list[str], environment: Mapping[str, str]) -> bool:
    """True when `argv` is a xacro call this process can do with identical results."""
    if not argv or os.path.basename(argv[0]) != "xacro":
        return False
    on_path = shutil.which(argv[0], path=environment.get("PATH", os.defpath))
    ours = os.path.join(sys.prefix, "bin", "xacro")
    return on_path is None or os.path.realpath(on_path) == os.path.realpath(ours)


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
    launcher.compat.enable_in_process()
    launcher.compat.current_index = index
    try:
        doc = xacro.process_file(input_file, **vars(options))
    except Exception as exc:  # xacro raises plain exceptions with good messages
        files = " (included from ".join(str(f) for f in reversed(xacro.filestack or []) if f)
        where = f"\n  in {files}{')' * (files.count('(included'))}" if files else ""
        message = str(exc) or repr(exc)
        raise ExecutionError(f"xacro failed: {message}{where}") from None
    return doc.toprettyxml(indent="  ")
