"""The command line: thin commands over the layers below.

This package's own module imports nothing heavy: the listing fast path (quick.py) is imported
through it, and argparse alone is a tenth of that path's budget.
"""

from __future__ import annotations

import math


def positive_number(text: str) -> float:
    """An argparse type: a finite number > 0 (a rate of 0 would divide by zero)."""
    try:
        value = float(text)
    except ValueError:
        raise _argument_error(f"expected a number, got '{text}'") from None
    if not math.isfinite(value) or value <= 0:
        raise _argument_error(f"expected a number > 0, got '{text}'")
    return value


def positive_count(text: str) -> int:
    """An argparse type: a whole number > 0 (a count of messages)."""
    try:
        value = int(text)
    except ValueError:
        raise _argument_error(f"expected a whole number, got '{text}'") from None
    if value <= 0:
        raise _argument_error(f"expected a whole number > 0, got '{text}'")
    return value


def _argument_error(text: str) -> Exception:
    import argparse

    return argparse.ArgumentTypeError(text)

