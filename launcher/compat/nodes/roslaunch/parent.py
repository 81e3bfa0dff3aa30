"""roslaunch.parent: ROSLaunchParent, what scripts and tests use to run launch files from
Python: `start()` loads the files and starts them on launcher's runtime in a thread of its
own (roslaunch.launch), `spin()` waits until the launch ends, `shutdown()` stops everything it
started."""

from __future__ import annotations

from typing import Any

from roslaunch.config import load_config_default
from roslaunch.core import RLException, printerrlog, printlog_bold  # noqa: F401
from roslaunch.launch import (
    DEFAULT_TIMEOUT_SIGINT,
    DEFAULT_TIMEOUT_SIGTERM,
    NUM_WORKERS,
    ROSLaunchRunner,
)


class ROSLaunchParent:
    """Runs `roslaunch_files` (each a path, or (path, ['name:=value', …])) and
    `roslaunch_strs` (launch XML) as one launch."""

    def __init__(self, run_id: str, roslaunch_files: list[Any], is_core: bool = False,
                 port: int | None = None, local_only: bool = False,
                 process_listeners: list[Any] | None = None, verbose: bool = False,
                 force_screen: bool = False, force_log: bool = False,
                 is_rostest: bool = False, roslaunch_strs: list[str] | None = None,
                 num_workers: int = NUM_WORKERS, timeout: float | None = None,
                 master_logger_level: Any = False, show_summary: bool = True,
                 force_required: bool = False,
                 sigint_timeout: float = DEFAULT_TIMEOUT_SIGINT,
                 sigterm_timeout: float = DEFAULT_TIMEOUT_SIGTERM) -> None:
        if force_screen and force_log:
            raise RLException("Can't specify both force_screen and force_log")
        self.run_id, self.roslaunch_files = run_id, list(roslaunch_files)
        self.roslaunch_strs = list(roslaunch_strs or [])
        self.is_core, self.is_rostest, self.port = is_core, is_rostest, port
        self.local_only, self.verbose, self.show_summary = local_only, verbose, show_summary
        self.force_screen, self.force_log, self.force_required = \
            force_screen, force_log, force_required
        self.process_listeners = list(process_listeners or [])
        self.num_workers, self.timeout = num_workers, timeout
        self.master_logger_level = master_logger_level
        self.sigint_timeout, self.sigterm_timeout = sigint_timeout, sigterm_timeout
        self.config: Any = None
        self.runner: ROSLaunchRunner | None = None
        self.pm = None
        self.server = None

    def _load_config(self) -> None:
        self.config = load_config_default(self.roslaunch_files, self.port,
                                          roslaunch_strs=self.roslaunch_strs,
                                          verbose=self.verbose)

    def start(self, auto_terminate: bool = True) -> None:
        """Load the files and start the launch (in its own thread). With `auto_terminate`,
        it ends once all its processes have; else it runs until shutdown()."""
        self._load_config()
        if self.show_summary:
            printlog_bold(self.config.summary(local=self.local_only))
        self.runner = ROSLaunchRunner(self.run_id, self.config, is_core=self.is_core,
                                      is_rostest=self.is_rostest,
                                      num_workers=self.num_workers, timeout=self.timeout,
                                      sigint_timeout=self.sigint_timeout,
                                      sigterm_timeout=self.sigterm_timeout)
        self.runner.auto_terminate = auto_terminate
        for listener in self.process_listeners:
            self.runner.add_process_listener(listener)
        self.runner.launch()

    def spin_once(self) -> None:
        """Let the launch run a moment."""
        if self.runner is not None:
            self.runner.spin_once()

    def spin(self) -> None:
        """Wait until the launch has ended, then shut it down."""
        if self.runner is None:
            raise RLException("parent not started yet")
        try:
            self.runner.spin()
        finally:
            self.shutdown()

    def shutdown(self) -> None:
        """Stop everything the launch started, and wait until it has stopped."""
        if self.runner is not None:
            self.runner.stop()
