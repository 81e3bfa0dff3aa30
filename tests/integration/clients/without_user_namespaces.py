"""Run a command as the user nobody where user namespaces cannot be made, as on a machine
that restricts them (run as root): `python without_user_namespaces.py CMD…`. The command
runs in a user namespace of its own (every id mapped to itself), whose limit of user
namespaces below it is 0, so its unshare(CLONE_NEWUSER) fails as a restricted one does."""

import ctypes
import os
import sys

CLONE_NEWUSER = 0x10000000
NOBODY = 65534


def child(mapped: int, unshared: int) -> None:
    libc = ctypes.CDLL(None, use_errno=True)
    if libc.unshare(CLONE_NEWUSER) != 0:
        sys.exit(f"unshare: {os.strerror(ctypes.get_errno())}")
    os.write(unshared, b"x")
    os.read(mapped, 1)  # the parent has written the maps
    with open("/proc/sys/user/max_user_namespaces", "w") as handle:
        handle.write("0")
    os.setgroups([])
    os.setresgid(NOBODY, NOBODY, NOBODY)
    os.setresuid(NOBODY, NOBODY, NOBODY)
    os.execvp(sys.argv[1], sys.argv[1:])


def main() -> int:
    mapped_r, mapped_w = os.pipe()
    unshared_r, unshared_w = os.pipe()
    pid = os.fork()
    if pid == 0:
        os.close(mapped_w)
        os.close(unshared_r)
        child(mapped_r, unshared_w)
    os.close(mapped_r)
    os.close(unshared_w)
    os.read(unshared_r, 1)
    for name in ("uid_map", "gid_map"):
        with open(f"/proc/{pid}/{name}", "w") as handle:
            handle.write("0 0 4294967295")
    os.write(mapped_w, b"x")
    _, status = os.waitpid(pid, 0)
    return os.waitstatus_to_exitcode(status)


if __name__ == "__main__":
    sys.exit(main())
