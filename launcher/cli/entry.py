"""The `launcher` command's first lines: from here on, Ctrl-C and SIGTERM end any command
cleanly, with the exit status a shell reports for them (130, 143) and no traceback.

The handlers come first, before any other import (`_signal` is the C module: `signal` would
import enum first). Until the command is done, either signal raises a KeyboardInterrupt
wherever the launcher is (importing, loading, evaluating); `launcher launch` takes them over
once its event loop runs. After the command, they end the process at once with that status.
A signal in the interpreter's own first milliseconds, before this module runs, is Python's:
SIGTERM ends it by the signal itself (the shell shows the same 143); a SIGINT raises Python's
KeyboardInterrupt where the interpreter is. One place swallows it: the check whether argv[0] (this
script) is an import path entry prints the KeyboardInterrupt and runs the script all the same
(CPython's pymain_get_importer). The interpreter keeps what it printed in `sys.last_value`, so the
first lines below see it and exit with 130, as if the signal had come a moment later.
"""

import _signal
import posix

_running = False  # main() has begun: from then on a signal raises, to be caught there
_raised = False  # one has been raised: the command is ending because of it
_unacted: list[tuple[int, str]] = []  # (signum, file:line) of each raised, until a launch's
# loop takes them


class _Interrupted(KeyboardInterrupt):  # launcher.errors.Interrupted, before it can be imported
    def __init__(self, signum: int) -> None:
        super().__init__(signum)
        self.signum = signum


def _interrupt(signum: int, _frame: object) -> None:
    global _raised
    trace = posix.environ.get(b"LAUNCHER_SIGNAL_TRACE")  # (runtime/loop.py's, for the bench)
    if trace:
        import time  # (a built-in module: only when tracing)

        fd = posix.open(trace, posix.O_WRONLY | posix.O_APPEND | posix.O_CREAT, 0o600)
        posix.write(fd, f"{time.time():.6f} {posix.getpid()} entry {signum} running={_running} "
                        f"raised={_raised} "
                        f"at {getattr(_frame, 'f_code', None) and _frame.f_code.co_filename}:"
                        f"{getattr(_frame, 'f_lineno', '?')}\n".encode())
        posix.close(fd)
    if not _running:  # still importing this module: nothing to clean up yet
        posix._exit(128 + signum)
    if _raised:  # one is on its way up already: raised again it could land in main()'s own
        _leave(signum, _frame)  # handling of the first and escape it; this one ends it now
    _raised = True
    where = f"{_frame.f_code.co_filename}:{_frame.f_lineno}" if _frame is not None else "?"
    _unacted.append((signum, where))
    raise _Interrupted(signum)


def _take_raised() -> list[tuple[int, str]]:
    """The signals raised so far, taken by a launch's event loop as it takes the signals over:
    a launch that is about to run although one was raised has had it swallowed on its way up
    (a user's `except BaseException:` in a launch file, a library's), and acts on it now."""
    taken = list(_unacted)
    _unacted.clear()
    return taken


_interrupt.take_raised = _take_raised  # (runtime/loop.py looks for it on the handler it replaces)
_signal.signal(_signal.SIGINT, _interrupt)
_signal.signal(_signal.SIGTERM, _interrupt)

import sys  # noqa: E402 - after the handlers, on purpose (a built-in module: no import runs)

if isinstance(getattr(sys, "last_value", None), KeyboardInterrupt):  # Ctrl-C the interpreter
    posix._exit(128 + _signal.SIGINT)  # printed and went on from (see above)

import atexit  # noqa: E402
import os  # noqa: E402


def _unraisable(info: "sys.UnraisableHookArgs") -> None:
    """A signal whose KeyboardInterrupt was raised where Python cannot raise (a weakref
    callback, as importing runs them; a __del__) is not lost with a printed traceback: it is
    sent again, from another thread so that it lands once this hook has returned (and again
    should it land in such a place again)."""
    signum = getattr(info.exc_value, "signum", None)
    if isinstance(info.exc_value, KeyboardInterrupt) and signum is not None:
        import _thread  # (this one's, or the event loop's Interrupted: runtime/loop.py)

        _thread.start_new_thread(os.kill, (os.getpid(), signum))
        return
    sys.__unraisablehook__(info)


sys.unraisablehook = _unraisable


@atexit.register  # registered first, so it runs last, just before Python's own teardown
def _hold_signals() -> None:
    """The command is done and the status decided: the interpreter's teardown resets the
    handlers it set to their defaults, and a signal landing after that would end the process
    by the signal, not with the status. So they are ignored from here to the exit: the
    teardown leaves an ignored signal ignored, and an ignored signal is ignored in every
    thread (a mask would hold it in this thread alone, and Zenoh's threads would take it)."""
    for sig in (_signal.SIGINT, _signal.SIGTERM):
        _signal.signal(sig, _signal.SIG_IGN)


def _leave(signum: int, _frame: object) -> None:
    for stream in (sys.stdout, sys.stderr):
        try:  # noqa: SIM105 - contextlib's imports are a tenth of a `topic list` (cli/quick.py)
            stream.flush()
        except (OSError, ValueError):
            pass
    os._exit(128 + signum)


def main() -> int:
    global _running
    try:
        _running = True
        code = None
        if sys.argv[-1:] == ["list"]:  # a listing the fast path may answer (cli/quick.py);
            from launcher.cli.quick import answer  # other commands never import it

            code = answer(sys.argv[1:])
        if code is None:
            from launcher.cli.main import main as run_command

            code = run_command()
    except KeyboardInterrupt as exc:
        code = 128 + getattr(exc, "signum", _signal.SIGINT)
    except Exception as exc:
        from launcher.errors import interrupt_behind  # (argparse's cleanup cut short)

        cause = interrupt_behind(exc)
        if cause is None:
            raise
        code = 128 + getattr(cause, "signum", _signal.SIGINT)
    for sig in (_signal.SIGINT, _signal.SIGTERM):
        _signal.signal(sig, _leave)
    return code
