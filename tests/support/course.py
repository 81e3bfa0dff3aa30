"""The course (the user's ROS 1 document in ../shared) and its publisher.py."""

from __future__ import annotations

from tests.support.environment import shared

COURSE = ("seeds", "000_a847380181b3b659.txt")  # the course, in ../shared


def course_text() -> str:
    return shared(*COURSE).read_text(encoding="utf-8")


def course_publisher() -> str:
    """publisher.py as the course prints it, from its #! line to the end of its code."""
    text = course_text()
    start = text.index("#!/usr/bin/env python")
    end = text.index("It was shown the commonly used plugins")
    return text[start:end].rstrip() + "\n"
