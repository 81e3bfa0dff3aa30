"""`python -m launch_testing.launch_test FILE …`: launcher's `launch_test` (`launcher test`),
run with this interpreter."""

from __future__ import annotations

import os
import sys


def main() -> None:
    os.execv(sys.executable, [sys.executable, "-m", "launcher", "test", *sys.argv[1:]])


if __name__ == "__main__":
    main()
