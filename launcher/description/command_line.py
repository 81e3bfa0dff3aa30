"""Split a `cmd` into arguments, shell-style, without ever splitting a substitution's value.

Quotes, backslashes and spaces in the launch file's own text are syntax; text that a
substitution produced is taken literally, whole. So `sh -c 'echo $(var msg)'` is three
arguments whatever `msg` holds (ROS 2 cannot quote across a substitution), and a `$(var path)`
with spaces stays one argument (as in ROS 2).
"""

from __future__ import annotations

from launcher.description.substitution import Text, Text_
from launcher.errors import SubstitutionError
from launcher.runtime.context import LaunchContext


def segments(context: LaunchContext, text: Text_) -> list[tuple[str, bool]]:
    """The performed text as (piece, is_syntax) pairs."""
    return [(s.text, True) if isinstance(s, Text) else (s.perform(context), False) for s in text]


def split_command(context: LaunchContext, text: Text_) -> list[str]:
    args: list[str] = []
    current: list[str] = []
    started = False  # an argument is open (even an empty quoted one)
    quote: str | None = None
    escaped = False
    for piece, syntax in segments(context, text):
        if not syntax:
            current.append(piece)
            started = started or bool(piece)
            continue
        for ch in piece:
            if escaped:
                current.append(ch)
                escaped = False
            elif quote is not None:
                if ch == quote:
                    quote = None
                elif ch == "\\" and quote == '"':
                    escaped = True
                else:
                    current.append(ch)
            elif ch in "'\"":
                quote, started = ch, True
            elif ch == "\\":
                escaped, started = True, True
            elif ch.isspace():
                if started:
                    args.append("".join(current))
                    current, started = [], False
            else:
                current.append(ch)
                started = True
    if quote is not None:
        raise SubstitutionError(f"unclosed quote {quote} in the command line")
    if started:
        args.append("".join(current))
    return args


def join_command(context: LaunchContext, text: Text_) -> str:
    """The performed text, unsplit (for `shell: true`)."""
    return "".join(piece for piece, _ in segments(context, text))
