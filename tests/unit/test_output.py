import io
import re

import pytest

from launcher.runtime.output import Printer, Record, plain


class Tty(io.StringIO):
    def isatty(self):
        return True


def test_plain_lines_without_a_terminal():
    out = io.StringIO()
    printer = Printer(out)
    printer.emit(Record("talker-1", "hello"))
    printer.emit(Record("launch", "started", "launcher", "INFO"))
    assert out.getvalue() == "[talker-1] hello\n[INFO] [launch]: started\n"


def test_colours_only_on_a_terminal_and_stable_per_name():
    out = Tty()
    printer = Printer(out)
    assert printer.color
    first = printer.format(Record("a-1", "x"))
    assert first.startswith("\x1b[") and first.endswith(" x")
    assert printer.format(Record("a-1", "y")).split(" ")[0] == first.split(" ")[0]
    assert "\x1b[31m" in printer.format(Record("launch", "bad", "launcher", "ERROR"))


def test_log_file_lines_have_a_timestamp():
    line = plain(Record("n-1", "text", time=12.5))
    assert line == "12.5000000 [n-1] text"


class _Terminal:
    def __init__(self, tty: bool) -> None:
        self.tty = tty

    def isatty(self) -> bool:
        return self.tty


@pytest.mark.parametrize("environ, tty, expected", [
    ({}, True, True),
    ({}, False, False),
    ({"NO_COLOR": "1"}, True, False),
    ({"NO_COLOR": ""}, True, True),  # (set but empty: as if not set)
    ({"FORCE_COLOR": "1"}, False, True),
    ({"FORCE_COLOR": "0"}, False, False),
    ({"RCUTILS_COLORIZED_OUTPUT": "1", "NO_COLOR": "1"}, False, True),  # ROS 2's own wins
    ({"RCUTILS_COLORIZED_OUTPUT": "0", "FORCE_COLOR": "1"}, True, False),
])
def test_colour_as_the_environment_says(environ, tty, expected):
    from launcher.runtime.output import color_wanted

    assert color_wanted(_Terminal(tty), environ) is expected


class SlowScreen(io.StringIO):
    """A screen that takes each write slowly (a terminal behind, a pipe read slowly)."""

    def __init__(self, hold) -> None:
        super().__init__()
        self.hold = hold

    def write(self, text: str) -> int:
        self.hold.wait(10)
        return super().write(text)


def test_a_slow_screen_drops_process_lines_past_its_backlog_and_says_how_many():
    import threading

    from launcher.runtime import output

    hold = threading.Event()
    screen = SlowScreen(hold)
    printer = Printer(out=screen, color=False)
    printer.start()
    line = "x" * 1000
    for _ in range(3 * output.SCREEN_BACKLOG // 1000):  # (never held up: the thread writes)
        printer.emit(Record("flood-1", line))
    printer.emit(Record("launch", "still said", "launcher", "WARN"))
    hold.set()
    printer.close()
    text = screen.getvalue()
    said = re.findall(r"\[launch\] (\d+) lines were not shown: the screen could not keep up",
                      text)
    dropped = sum(int(count) for count in said)
    assert dropped > 0
    assert "[WARN] [launch]: still said" in text  # (the launcher's own: never dropped)
    assert text.count("[flood-1] ") == 3 * output.SCREEN_BACKLOG // 1000 - dropped
