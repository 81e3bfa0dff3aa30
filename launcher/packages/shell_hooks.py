"""`.sh` (and `.bash`) hooks, run in a real shell with ament's helper functions defined.

The hook file runs as `sh -c '<helpers>; . HOOK'` with AMENT_CURRENT_PREFIX and
COLCON_CURRENT_PREFIX set to the package's prefix; the environment it leaves is read back
(`env -0`). A hook that fails is reported with its exit status and stderr.
"""

from __future__ import annotations

import subprocess
from pathlib import Path

from launcher.errors import ExecutionError, Location

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
    result = subprocess.run([shell, "-c", script], env=hook_env, capture_output=True,
                            stdin=subprocess.DEVNULL, check=False)
    if result.returncode != 0:
        stderr = result.stderr.decode(errors="replace").strip()
        raise ExecutionError(f"hook failed with exit status {result.returncode}"
                             + (f"; its stderr:\n{stderr}" if stderr else ""), Location(str(path)))
    after = {}
    for item in result.stdout.split(b"\0"):
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
