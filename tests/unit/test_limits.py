"""No input can hang or flood the launcher: $(eval) sizes, loop lengths, files that are not
files, and text that would forge a line of the launcher's output."""

from __future__ import annotations

import os
import threading

import pytest

from launcher.description.safe_expression import ExpressionError, evaluate
from launcher.errors import LaunchError
from launcher.runtime.output import Printer, Record, plain
from launcher.user_files import read_bytes, read_text

HOSTILE = {
    "math.factorial(100000000)": "factorial(100000000) would be too large",
    "math.comb(10**9, 10**8)": "comb(1000000000, 100000000) would be too large",
    "math.perm(10**6)": "perm(1000000) would be too large",
    "math.prod([10**999]*999999)": "the product would be too large",
    "((10**1000)**1000)**1000": "would be too large",
    "10**10**6": "10 ** 1000000 would be too large",
    "(2**99999)**2": "(an integer of 100000 bits) ** 2 would be too large",
    '"%0999999999d" % 1': "the width 999999999 is past the limit",
    '"%.999999999f" % 1.0': "the width 999999999 is past the limit",
    "'%*d' % (10**9, 1)": "'*' widths are not allowed",
    '"x".zfill(10**9)': "the string would be too large",
    '("x"*999999).replace("x", "yy")': "the string would be too large",
    '",".join(["abc"]*999999)': "the string would be too large",
    "round(1, -10**9)": "past the limit",
    "[0] * 10**9": "the result would be too large",
    "-" * 5000 + "1": "nested too deeply",
    "1 + " * 60000 + "1": "characters long",
}


@pytest.mark.parametrize("expression", list(HOSTILE))
def test_eval_refuses_what_would_hang_or_flood(expression):
    """Refused before the work starts: each returns at once (a runaway one would hold this
    thread; the test gives it ten seconds, far more than any of them takes when refused)."""
    outcome: list[BaseException] = []

    def run() -> None:
        try:
            evaluate(expression)
        except BaseException as exc:  # noqa: BLE001 - handed to the test thread
            outcome.append(exc)

    worker = threading.Thread(target=run, daemon=True)
    worker.start()
    worker.join(10)
    assert not worker.is_alive(), f"{expression[:40]} still running"
    assert outcome and isinstance(outcome[0], ExpressionError), outcome
    assert HOSTILE[expression] in str(outcome[0])


@pytest.mark.parametrize("expression, value", [
    ("math.factorial(20)", 2432902008176640000), ("math.comb(10, 3)", 120),
    ("'%05.2f' % 3.14159", "03.14"), ("str(7).zfill(3)", "007"), ("2**64", 2**64),
    ("'-'.join(['a', 'b'])", "a-b"), ("'a_b'.replace('_', '/')", "a/b"),
    ("math.prod([2, 3, 4])", 24), ("round(2.567, 2)", 2.57),
])
def test_eval_still_does_what_launch_files_need(expression, value):
    assert evaluate(expression) == value


def test_a_fifo_or_device_is_refused_before_anything_blocks(tmp_path):
    fifo = tmp_path / "world.sdf"
    os.mkfifo(fifo)
    with pytest.raises(LaunchError, match="a FIFO .named pipe., not a regular file"):
        read_text(fifo)  # opening a FIFO to read would wait for a writer for ever
    with pytest.raises(LaunchError, match="a character device, not a regular file"):
        read_bytes("/dev/zero")
    (tmp_path / "zero.launch.yaml").symlink_to("/dev/zero")
    with pytest.raises(LaunchError, match="a character device"):
        read_bytes(tmp_path / "zero.launch.yaml")
    with pytest.raises(IsADirectoryError):
        read_bytes(tmp_path)


def test_an_oversized_file_is_refused_unread(tmp_path):
    big = tmp_path / "huge.urdf"
    with open(big, "wb") as handle:
        handle.truncate(65 << 20)  # sparse: nothing is written, and nothing should be read
    with pytest.raises(LaunchError, match="larger than 64 MiB"):
        read_bytes(big)
    assert read_bytes(big, limit=100 << 20)[:4] == b"\0\0\0\0"


def test_a_value_with_a_newline_cannot_forge_a_launcher_line():
    forged = "a\n[ERROR] [launch]: forged\rmore"
    record = Record("launch", f"x={forged}", "launcher", "INFO")
    for text in (Printer(color=False).format(record), plain(record)):
        lines = text.split("\n")
        assert len(lines) == 2
        assert lines[1] == "    [ERROR] [launch]: forged\\rmore"
