"""launch_testing.asserts (launcher.compat.testing)."""

from launcher.compat.testing.asserts import (
    EXIT_FORCED,  # noqa: F401
    EXIT_OK,
    EXIT_SIGINT,
    EXIT_SIGKILL,
    EXIT_SIGQUIT,
    EXIT_SIGSEGV,
    SequentialTextChecker,
    assertDefaultStream,
    assertExitCodes,
    assertInStderr,
    assertInStdout,
    assertInStream,
    assertSequentialStdout,
)
from launcher.compat.testing.tools.output import remove_ansi_escape_sequences  # noqa: F401
from launcher.compat.testing.tools.text import build_text_match  # noqa: F401
from launcher.compat.testing.util import (
    NO_CMD_ARGS,
    resolveProcesses,  # noqa: F401
)

__all__ = [
    "EXIT_OK", "EXIT_SIGINT", "EXIT_SIGKILL", "EXIT_SIGQUIT", "EXIT_SIGSEGV", "NO_CMD_ARGS",
    "SequentialTextChecker", "assertDefaultStream", "assertExitCodes", "assertInStderr",
    "assertInStdout", "assertInStream", "assertSequentialStdout"
]
