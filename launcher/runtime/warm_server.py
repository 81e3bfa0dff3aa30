"""The warm start's server: `python -m launcher.runtime.warm_server --fd=N`.

The launcher starts one (runtime/warm.py) with the environment its Python processes get. Its
first request (below) is {"modules": [MODULE, …]}: it imports each MODULE (rclpy, the message
packages nodes use: the compat finder is installed at its start, as in every Python process a
launch starts), starts no thread, and then forks each Python process the launch asks for: the
process finds those modules imported, and does not spend its start importing them again.

Requests come on fd N, a Unix stream socket: a length (8 bytes, with the process's stdin,
stdout and stderr as SCM_RIGHTS), then that many bytes of JSON: {"argv": […], "env": {…},
"cwd": "…", "run": "script" | "module", "target": path or module name}. The answer is a JSON
line, {"pid": N}. The server forks a go-between that forks the process and exits at once: the
process is reparented to the launcher (the child subreaper) and is its child from then on, as
one it started itself. The server ends when the socket does (the launcher gone).

In the process, before its code runs, everything an interpreter started afresh would have is
set as it would be: a session of its own, its stdio, working directory, environment, argv,
sys.path, the signal dispositions of a new interpreter, a new `__main__`, stdio streams with
the buffering its environment asks for. A failure is said as the interpreter says it (the
traceback from the script's own frame, SyntaxError as Python prints it), with its status.
"""

from __future__ import annotations

import contextlib
import ctypes
import importlib
import io
import json
import os
import signal
import socket
import sys
from pathlib import Path

LENGTH = 8  # bytes of a request's length
HERE = __file__  # (this module runs as __main__: a process gets a __main__ of its own)


def main() -> int:
    channel = socket.socket(fileno=int(sys.argv[1].removeprefix("--fd=")))
    first = _receive(channel)  # (what to import: not on its command line, where `pgrep -f
    if first is None:          # NODE` would take this server for the node)
        return 0
    # (sys.path[0] is the launcher's folder: not what the processes import from, each has its
    # own first entry)
    base_path = sys.path[:] = sys.path[1:]
    for name in first[0].get("modules", []):
        try:
            importlib.import_module(name)
        except Exception:  # noqa: BLE001 - the process imports it itself then, as cold
            continue
    # (ready, or not: a process this server would start could not look as it would cold, or
    # an import started a thread, which a fork would not carry over)
    ready = len(os.listdir("/proc/self/task")) == 1 and _can_appear()
    channel.sendall(json.dumps({"ready": ready}).encode() + b"\n")
    while True:
        request = _receive(channel)
        if request is None:
            return 0
        fields, fds = request
        pid = _start(fields, fds, channel, base_path)
        channel.sendall(json.dumps({"pid": pid}).encode() + b"\n")


def _receive(channel: socket.socket) -> tuple[dict, list[int]] | None:
    """The next request, or None at the socket's end."""
    try:
        header, fds, _, _ = socket.recv_fds(channel, LENGTH, 3)
    except (ConnectionError, OSError):
        return None
    if len(header) < LENGTH:
        for fd in fds:
            os.close(fd)
        return None
    size = int.from_bytes(header, "little")
    body = bytearray()
    while len(body) < size:
        chunk = channel.recv(size - len(body))
        if not chunk:
            return None
        body += chunk
    return json.loads(body), fds


def _start(fields: dict, fds: list[int], channel: socket.socket, base_path: list[str]) -> int:
    """Fork the process (through a go-between, see above); its pid, which the process says
    itself once it is in a session of its own (a stop signal to its group reaches it from
    the first moment the launcher knows it), or -1. In the process itself this does not
    return: its SystemExit ends the interpreter as `python script.py` ends."""
    read, write = os.pipe()
    go_between = os.fork()
    if go_between == 0:
        try:
            if os.fork() != 0:
                os._exit(0)
        except BaseException:  # noqa: BLE001 - said to the launcher as no pid
            os._exit(1)
        os.close(read)
        channel.close()
        if not _appear_as(fields["shown"], fields["env"], fields["comm"]):
            os._exit(127)  # (checked at the server's start: not met here)
        os.setsid()
        os.write(write, str(os.getpid()).encode())
        os.close(write)
        _run(fields, fds, base_path)
    os.close(write)
    for fd in fds:
        os.close(fd)
    told = b""
    while chunk := os.read(read, 64):
        told += chunk
    os.close(read)
    os.waitpid(go_between, 0)
    return int(told) if told else -1


def _run(fields: dict, fds: list[int], base_path: list[str]) -> None:
    """Become the process the request describes and run it; exits with its status."""
    for target, fd in enumerate(fds):
        os.dup2(fd, target)
    for name in os.listdir("/proc/self/fd"):  # (only stdio, as a process started cold has)
        if int(name) > 2:
            with contextlib.suppress(OSError):
                os.close(int(name))
    os.environ.clear()
    os.environ.update(fields["env"])
    os.chdir(fields["cwd"])
    signal.signal(signal.SIGINT, signal.default_int_handler)  # (a new interpreter's own)
    for name in ("random", "numpy.random"):  # (seeded afresh, as a new interpreter's import
        if name in sys.modules:              # seeds them)
            sys.modules[name].seed()
    _streams()
    if fields["run"] == "module":
        import runpy

        sys.argv = ["-m", *fields["argv"]]  # (as `python -m`: runpy sets argv[0] to its file)
        sys.path[:] = [os.getcwd(), *base_path]
        _fresh_main()  # (runpy runs the module in __main__'s namespace: not this module's)
        _exit_as_python(lambda: runpy._run_module_as_main(fields["target"]))  # type: ignore[attr-defined]
    script = fields["target"]
    sys.argv = [fields["shown"][1], *fields["argv"]]  # (the script as the interpreter was
    sys.path[:] = [os.path.dirname(os.path.realpath(script)), *base_path]  # given it)
    _exit_as_python(lambda: _run_script(script))


class _MemoryMap(ctypes.Structure):  # the kernel's struct prctl_mm_map
    _fields_ = [*((name, ctypes.c_uint64) for name in (
        "start_code", "end_code", "start_data", "end_data", "start_brk", "brk", "start_stack",
        "arg_start", "arg_end", "env_start", "env_end")),
        ("auxv", ctypes.c_void_p), ("auxv_size", ctypes.c_uint32), ("exe_fd", ctypes.c_uint32)]


PR_SET_NAME, PR_SET_MM, PR_SET_MM_MAP = 15, 35, 14
_shown: list[ctypes.Array] = []  # (the memory /proc shows the process's argv and environ from)


def _appear_as(argv: list[str], env: dict[str, str], comm: str) -> bool:
    """/proc/PID/cmdline, /proc/PID/environ and comm as the process started cold would have
    them (ps, pgrep -f, psutil, and the launch's mark for lineage.py): the kernel's record of
    where argv and environ lie is pointed at a copy of the process's own (prctl PR_SET_MM_MAP,
    which needs no privilege when the executable is left as it is)."""
    libc = ctypes.CDLL(None, use_errno=True)
    stat = Path("/proc/self/stat").read_text().rsplit(")", 1)[1].split()

    def field(number: int) -> int:  # (proc(5)'s numbering; the list starts at field 3)
        return int(stat[number - 3])

    args = b"".join(word.encode(errors="surrogateescape") + b"\0" for word in argv)
    environ = b"".join(f"{k}={v}".encode(errors="surrogateescape") + b"\0"
                       for k, v in env.items())
    memory = ctypes.create_string_buffer(args + environ, len(args) + len(environ))
    start = ctypes.addressof(memory)
    libc.sbrk.restype = ctypes.c_void_p
    layout = _MemoryMap(
        start_code=field(26), end_code=field(27), start_data=field(45), end_data=field(46),
        start_brk=field(47), brk=libc.sbrk(0), start_stack=field(28), arg_start=start,
        arg_end=start + len(args), env_start=start + len(args),
        env_end=start + len(args) + len(environ), auxv=None, auxv_size=0, exe_fd=0xFFFFFFFF)
    if libc.prctl(PR_SET_MM, PR_SET_MM_MAP, ctypes.byref(layout), ctypes.sizeof(layout), 0):
        return False
    _shown.append(memory)
    libc.prctl(PR_SET_NAME, comm.encode()[:15], 0, 0, 0)
    return True


def _can_appear() -> bool:
    """Whether a process forked here can be given its own argv and environ (the kernel has
    PR_SET_MM_MAP): tried in a child of its own."""
    pid = os.fork()
    if pid == 0:
        os._exit(0 if _appear_as([sys.executable], dict(os.environ), "python3") else 1)
    _, status = os.waitpid(pid, 0)
    return os.waitstatus_to_exitcode(status) == 0


def _streams() -> None:
    """stdin, stdout and stderr on fds 0-2 as a new interpreter makes them: stdout
    line-buffered on a terminal and written through under PYTHONUNBUFFERED, stderr always
    line-buffered; the encodings the server's own got (its environment's locale is the
    process's: runtime/warm.py starts a process warm only then)."""
    unbuffered = bool(os.environ.get("PYTHONUNBUFFERED"))

    def stream(fd: int, old: io.TextIOWrapper, writing: bool) -> io.TextIOWrapper:
        raw = io.FileIO(fd, "w" if writing else "r", closefd=False)
        if not writing:
            return io.TextIOWrapper(io.BufferedReader(raw), encoding=old.encoding,
                                    errors=old.errors)
        return io.TextIOWrapper(raw if unbuffered else io.BufferedWriter(raw),
                                encoding=old.encoding, errors=old.errors,
                                line_buffering=fd == 2 or (os.isatty(fd) and not unbuffered),
                                write_through=unbuffered)

    sys.stdin = sys.__stdin__ = stream(0, sys.__stdin__, False)
    sys.stdout = sys.__stdout__ = stream(1, sys.__stdout__, True)
    sys.stderr = sys.__stderr__ = stream(2, sys.__stderr__, True)


def _fresh_main() -> dict:
    """A new `__main__`, as a new interpreter has, in place of this module; its namespace."""
    import builtins
    import types

    main_module = types.ModuleType("__main__")
    main_module.__builtins__ = builtins  # type: ignore[attr-defined]
    sys.modules["__main__"] = main_module
    return main_module.__dict__


def _run_script(path: str) -> None:
    import tokenize

    namespace = _fresh_main()
    namespace.update(__file__=path, __cached__=None)
    with tokenize.open(path) as source:  # (its encoding as Python reads it: PEP 263)
        code = compile(source.read(), path, "exec", dont_inherit=True)  # (not this module's
        # __future__ imports)
    exec(code, namespace)  # noqa: S102 - the user's own program, as python runs it


def _exit_as_python(run) -> None:  # type: ignore[no-untyped-def]
    """Run it; exit as the interpreter would after it: 0, SystemExit's status, 1 after an
    uncaught exception (printed without this module's frames), or by SIGINT itself after an
    uncaught KeyboardInterrupt."""
    try:
        run()
    except SystemExit:
        raise
    except BaseException as exc:  # noqa: BLE001 - what the interpreter would print
        tb = exc.__traceback__
        while tb is not None and tb.tb_frame.f_code.co_filename == HERE:
            tb = tb.tb_next  # (the script's own frames, as `python script.py` shows them)
        if isinstance(exc, SyntaxError) and tb is not None and \
                tb.tb_frame.f_code.co_filename.endswith("tokenize.py"):
            tb = None
        sys.excepthook(type(exc), exc.with_traceback(tb), tb)  # (the hook prints the
        # exception's own traceback)
        if isinstance(exc, KeyboardInterrupt):
            _die_by_sigint()
        sys.exit(1)
    sys.exit(0)


def _die_by_sigint() -> None:
    """As the interpreter ends after an uncaught KeyboardInterrupt: its exit handlers run,
    then it kills itself with SIGINT, so that its parent sees it ended by the signal."""
    import atexit
    import threading

    for thread in threading.enumerate():  # (the interpreter waits for them first)
        if thread is not threading.main_thread() and not thread.daemon:
            thread.join()
    atexit._run_exitfuncs()
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(OSError, ValueError):
            stream.flush()
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    os.kill(os.getpid(), signal.SIGINT)
    os._exit(130)


if __name__ == "__main__":
    sys.exit(main())
