"""The command line: thin commands over the layers below."""

from __future__ import annotations

import argparse
import math


def positive_number(text: str) -> float:
    """An argparse type: a finite number > 0 (a rate of 0 would divide by zero)."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number, got '{text}'") from None
    if not math.isfinite(value) or value <= 0:
        raise argparse.ArgumentTypeError(f"expected a number > 0, got '{text}'")
    return value


def positive_count(text: str) -> int:
    """An argparse type: a whole number > 0 (a count of messages)."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a whole number, got '{text}'") from None
    if value <= 0:
        raise argparse.ArgumentTypeError(f"expected a whole number > 0, got '{text}'")
    return value
