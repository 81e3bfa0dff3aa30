"""roslaunch's `$(…)` grammar (ROS 1's substitution_args), read into the same calls as ROS 2's
(substitution_parser.Call), naming launcher's substitutions.

roslaunch's rules differ from ROS 2's: inside `$(…)` the words are split at spaces, with no
quoting and no substitution inside another; `$(arg NAME)`, `$(env NAME)`, `$(anon NAME)` and
`$(find PKG)` take one word; `$(optenv NAME DEFAULT…)`'s default is every word after the name;
`$(dirname)` none; `$(eval EXPRESSION)` is the whole attribute and its expression everything
between `$(eval ` and the last `)`, taken as it is. An unclosed `$(` is an error here (roslaunch
keeps it as text, and passes the typo on: see the fidelity page's choices).
"""

from __future__ import annotations

from launcher.errors import did_you_mean
from launcher.frontend.substitution_parser import Call, Part, SubstitutionSyntaxError

# roslaunch's name → (launcher's substitution, how many words it takes: None for "any")
ROSLAUNCH = {"arg": ("var", 1), "env": ("roslaunch_env", 1), "optenv": ("roslaunch_env", None),
             "anon": ("anon", 1), "find": ("find-pkg-share", 1), "dirname": ("dirname", 0)}
EVAL = "roslaunch_eval"


def parse_roslaunch(text: str) -> tuple[Part, ...]:
    """Split `text` into literal strings and calls, by roslaunch's rules."""
    if text.startswith("$(eval ") and text.endswith(")"):
        return (Call(EVAL, ((text[len("$(eval "):-1],),), 0),)
    parts: list[Part] = []
    position = 0
    while (start := text.find("$(", position)) >= 0:
        end = text.find(")", start)
        if end < 0:
            raise SubstitutionSyntaxError(f"unclosed '{text[start:start + 12]}': expected ')'",
                                          start)
        inner = text[start + 2:end]
        if "$" in inner:
            raise SubstitutionSyntaxError("roslaunch takes no '$' inside a substitution (one "
                                          "substitution cannot hold another)", start)
        if text[position:start]:
            parts.append(text[position:start])
        parts.append(_call([w for w in inner.split(" ") if w], start))
        position = end + 1
    if text[position:]:
        parts.append(text[position:])
    return tuple(parts)


def _call(words: list[str], offset: int) -> Call:
    if not words:
        raise SubstitutionSyntaxError("empty substitution '$()'", offset)
    name, args = words[0], words[1:]
    if name == "eval":
        raise SubstitutionSyntaxError("roslaunch evaluates $(eval …) only as the whole "
                                      "attribute", offset)
    if name not in ROSLAUNCH:
        raise SubstitutionSyntaxError(
            f"unknown roslaunch substitution '$({name})'{did_you_mean(name, ROSLAUNCH)}; "
            f"roslaunch's are {', '.join([*ROSLAUNCH, 'eval'])}", offset)
    target, count = ROSLAUNCH[name]
    if count is None:  # optenv: the name, then the default: everything after it
        if not args:
            raise SubstitutionSyntaxError("$(optenv) needs a variable's name: "
                                          "$(optenv NAME [DEFAULT])", offset)
        args = [args[0], " ".join(args[1:])]
    elif len(args) != count:
        wanted = {0: "no word", 1: "exactly one word"}[count]
        raise SubstitutionSyntaxError(f"$({name}) takes {wanted} in roslaunch, got "
                                      f"{len(args)}: '$({' '.join(words)})'", offset)
    return Call(target, tuple((arg,) for arg in args), offset)
