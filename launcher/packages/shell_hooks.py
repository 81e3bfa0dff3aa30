"""`.sh` (and `.bash`) hooks, run in a real shell with ament's helper functions defined.

The hook file runs as `sh -c '<helpers>; . HOOK'` with AMENT_CURRENT_PREFIX and
COLCON_CURRENT_PREFIX set to the package's prefix; the environment it leaves is read back
(`env -0`). A hook that fails is reported with its exit status and stderr; one that does not
finish within LAUNCHER_HOOK_TIMEOUT seconds (default 60) is stopped, with all it started.
Either is located at the hook's line: the one the shell's message names, else the last
command the hook ran (the shell traces each command; bash says its line, and for sh, whose
Debian build has no $LINENO, the traced command is found in the file, in order). A background
job the hook starts is stopped when the hook is done, and never holds the launch up
(lineage.run_to_end).
"""

from __future__ import annotations

import re
import subprocess
from pathlib import Path

from launcher.errors import ExecutionError, Location
from launcher.lineage import run_to_end

HOOK_TIMEOUT = 60.0  # seconds, unless LAUNCHER_HOOK_TIMEOUT says
TIMEOUT_VARIABLE = "LAUNCHER_HOOK_TIMEOUT"
MARK = "\x1f"  # starts each line the shell traces (PS4): the hook's own stderr never does
_TRACED = re.compile(f"^{MARK}+(.*?){MARK}(\\d*){MARK} (.*)$")  # file, line, command

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
    script = (f"{HELPERS}\nPS4='{MARK}${{BASH_SOURCE:-}}{MARK}${{LINENO:-}}{MARK} '\n"
              'set -x\n. "$LAUNCHER_HOOK" || exit $?\nset +x\nexec env -0\n')
    hook_env = {**env, "AMENT_CURRENT_PREFIX": str(prefix), "COLCON_CURRENT_PREFIX": str(prefix),
                "LAUNCHER_HOOK": str(script_path)}
    timeout = hook_timeout(env)
    try:
        code, stdout, stderr = run_to_end([shell, "-c", script], hook_env, timeout=timeout)
    except subprocess.TimeoutExpired as exc:
        trace = (exc.stderr or b"").decode(errors="replace")
        raise ExecutionError(f"hook did not finish within {timeout:g} s and was stopped, with "
                             f"all it started (a hook sets variables; is it waiting for "
                             f"something? {TIMEOUT_VARIABLE} sets how long a hook may take)",
                             Location(str(path), last_line(trace, script_path))) from None
    text = stderr.decode(errors="replace")
    if code != 0:
        said = "\n".join(line for line in text.splitlines() if MARK not in line).strip()
        where = hook_location(path, said)
        if not where.line:
            where = Location(str(path), last_line(text, script_path))
        raise ExecutionError(f"hook failed with exit status {code}"
                             + (f"; its stderr:\n{said}" if said else ""), where)
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


def hook_timeout(env: dict[str, str]) -> float:
    """LAUNCHER_HOOK_TIMEOUT of the environment the hooks run in (seconds > 0), or 60."""
    text = env.get(TIMEOUT_VARIABLE)
    if not text:
        return HOOK_TIMEOUT
    try:
        value = float(text)
    except ValueError:
        value = -1.0
    if not value > 0:
        raise ExecutionError(f"{TIMEOUT_VARIABLE} is '{text}'; expected a number of seconds "
                             "> 0")
    return value


def last_line(trace: str, script_path: Path) -> int:
    """The hook's line that ran last, from the shell's trace (0 when none is found)."""
    try:
        lines = script_path.read_text(encoding="utf-8", errors="replace").splitlines()
    except OSError:
        return 0
    patterns = [_line_pattern(line) for line in lines]  # each line's commands
    found = 0
    for entry in trace.splitlines():
        traced = _TRACED.match(entry)  # (bash repeats PS4's first mark once per depth)
        if traced is None:
            continue
        source, number, command = traced.group(1), traced.group(2), traced.group(3).strip()
        if source:  # bash names the file and line
            if Path(source) == script_path and number.isdigit():
                found = int(number)
            continue
        found = _find(patterns, command, found) or found
    return found


def _find(patterns: list[list[re.Pattern[str]]], command: str, after: int) -> int:
    """The first line from `after` on (then from the top) that the traced command is a part
    of."""
    order = [*range(max(after - 1, 0), len(patterns)), *range(0, max(after - 1, 0))]
    for index in order:
        if any(part.fullmatch(command) for part in patterns[index]):
            return index + 1
    return 0


def _line_pattern(line: str) -> list[re.Pattern[str]]:
    """What the shell may trace for a line: each command of it (split at ;, &&, ||, |, and
    without if/then/do…), its words, a variable being any text."""
    text = line.split(" #", 1)[0].strip()
    if not text or text.startswith("#"):
        return []
    found = []
    for part in re.split(r"&&|\|\||;|\|", text):
        words = part.split()
        while words and words[0] in _KEYWORDS:
            words.pop(0)
        if words:
            pieces = re.split(r"\$\{[^}]*\}|\$\w+|[\"']", " ".join(words))
            found.append(re.compile(".*".join(re.escape(p) for p in pieces)))
    return found


_KEYWORDS = {"if", "then", "else", "elif", "fi", "do", "done", "while", "until", "!", "{", "}"}
