"""actionlib.handle_tracker_deleter: called when the last handle to a goal goes, it starts the
time after which the server's status list drops the goal."""

from __future__ import annotations

from typing import Any

import rospy


class HandleTrackerDeleter:
    def __init__(self, action_server: Any, status_tracker: Any) -> None:
        self.action_server, self.status_tracker = action_server, status_tracker

    def __call__(self, ptr: Any) -> None:
        """The goal's last handle is gone: its status is kept a timeout more from now."""
        if self.action_server:
            with self.action_server.lock:
                self.status_tracker.handle_destruction_time = rospy.Time.now()
