"""`.sh` (and `.bash`) hooks, run in a real shell with ament's helper functions defined.

The hook file runs as `sh -c '<helpers>; . HOOK'` with AMENT_CURRENT_PREFIX and
COLCON_CURRENT_PREFIX set to the package's prefix; the environment it leaves is read back
(`env -0`). A hook that fails is reported with its exit status and stderr (at the line the
shell names). A background job the hook starts is stopped when the hook is done, and never
holds the launch up (lineage.run_to_end).
"""

from __future__ import annotations

import re
import subprocess
from pathlib import Path

from launcher.errors import ExecutionError, Location
from launcher.lineage import run_to_end

HOOK_TIMEOUT = 60.0  # seconds

# ament_package's shell functions, written for POSIX sh.
HELPERS = r'''
ament_prepend_unique_value() {
  eval "_lv=\"\${$1:-}\""
  case ":$_lv:" in *":$2:"*) ;; *) if [ -z "$_lv" ]; then eval "export $1=\"\$2\"";
    else eval "export $1=\"\$2:\$_lv\""; fi ;; esac
}
ament_append_unique_value() {
  eval "_lv=\"\${$1:-}\""
  case ":$_lv:" in *":$2:"*) ;; *) if [ -z "$_lv" ]; then eval "export $1=\"\$2\"";
    else eval "export $1=\"\$_lv:\$2\""; fi ;; esac
}
ament_append_value() {
  eval "_lv=\"\${$1:-}\""
  if [ -z "$_lv" ]; then eval "export $1=\"\$2\""; else eval "export $1=\"\$_lv:\$2\""; fi
}
'''


def run_shell_hook(path: Path, script_path: Path, prefix: Path, env: dict[str, str],
                   shell: str = "sh") -> dict[str, str]:
    """The environment after sourcing `script_path` (the configured form of hook `path`)."""
    script = f'{HELPERS}\n. "$LAUNCHER_HOOK" || exit $?\nexec env -0\n'
    hook_env = {**env, "AMENT_CURRENT_PREFIX": str(prefix), "COLCON_CURRENT_PREFIX": str(prefix),
                "LAUNCHER_HOOK": str(script_path)}
    try:
        code, stdout, stderr = run_to_end([shell, "-c", script], hook_env, timeout=HOOK_TIMEOUT)
    except subprocess.TimeoutExpired:
        raise ExecutionError(f"hook did not finish within {HOOK_TIMEOUT:g} s (a hook sets "
                             f"variables; is it waiting for something?)",
                             Location(str(path))) from None
    if code != 0:
        text = stderr.decode(errors="replace").strip()
        raise ExecutionError(f"hook failed with exit status {code}"
                             + (f"; its stderr:\n{text}" if text else ""),
                             hook_location(path, text))
    after = {}
    for item in stdout.split(b"\0"):
        if b"=" in item:
            key, _, value = item.partition(b"=")
            after[key.decode(errors="replace")] = value.decode(errors="replace")
    for key in ("AMENT_CURRENT_PREFIX", "COLCON_CURRENT_PREFIX", "LAUNCHER_HOOK", "_lv",
                "PWD", "OLDPWD", "SHLVL", "_"):
        if key not in env:
            after.pop(key, None)
        else:
            after[key] = env[key]
    return after


def hook_location(path: Path, stderr: str) -> Location:
    """The hook's file, at the line the shell's message names (`…: 3: Syntax error…`,
    `…: line 3: …`) when it names one."""
    found = re.search(r"(?:line |: )(\d+): ", stderr)
    return Location(str(path), int(found.group(1)) if found else 0)
