"""A signal that lands inside a library's `try` whose cleanup then fails (argparse's
parse_intermixed_args restores attributes it never saved) is reported as the signal: the
status a shell expects, and nothing printed (found by the fault campaign)."""

from __future__ import annotations

from launcher.errors import Interrupted, report


def test_a_failure_while_handling_a_signal_is_the_signals(capsys):
    try:
        try:
            raise Interrupted(15)
        finally:
            raise AttributeError("'_StoreAction' object has no attribute 'save_nargs'")
    except AttributeError as exc:
        assert report(exc) == 143
    assert capsys.readouterr().err == ""


def test_other_failures_are_still_reported(capsys):
    try:
        try:
            raise ValueError("first")
        finally:
            raise AttributeError("second")
    except AttributeError as exc:
        assert report(exc) == 1
    assert "internal error: AttributeError: second" in capsys.readouterr().err
