"""actionlib.action_server: ActionServer, the goal-handle server on ROS 1's action topics. It
keeps a StatusTracker per goal, hands the user's goal and cancel callbacks a ServerGoalHandle,
and publishes the status list (latched) at `actionlib_status_frequency` (5 Hz), each ended
goal kept in it for `<ns>/status_list_timeout` seconds (5)."""

from __future__ import annotations

import threading
from typing import Any

import rospy
from actionlib_msgs.msg import GoalID, GoalStatusArray

from actionlib import status as S
from actionlib.exceptions import ActionException  # noqa: F401 (action_server has it)
from actionlib.goal_id_generator import GoalIDGenerator
from actionlib.handle_tracker_deleter import HandleTrackerDeleter
from actionlib.server_goal_handle import ServerGoalHandle
from actionlib.status_tracker import StatusTracker

PUB_QUEUE_SIZE = 50  # actionlib's defaults
STATUS_FREQUENCY = 5.0  # Hz
STATUS_LIST_TIMEOUT = 5.0  # s


def nop_cb(goal_handle: Any) -> None:
    """A goal or cancel callback that does nothing (ActionServer's default)."""


class ActionServer:
    def __init__(self, ns: str, ActionSpec: Any, goal_cb: Any,  # noqa: N803 (actionlib's)
                 cancel_cb: Any = nop_cb, auto_start: bool = True) -> None:
        """`goal_cb(handle)` hears each new goal, `cancel_cb(handle)` each cancel request
        for a goal; `auto_start`: start now (actionlib advises False, then start())."""
        if goal_cb is None:
            raise ActionException(f"ActionServer {ns!r}: goal_cb is None; give a function "
                                  "that takes each new goal's ServerGoalHandle")
        self.ns = ns
        types = S.message_types(ActionSpec)
        self.ActionSpec = ActionSpec
        self.ActionGoal, self.ActionResult = types["ActionGoal"], types["ActionResult"]
        self.ActionResultType, self.ActionFeedback = types["Result"], types["ActionFeedback"]
        self.goal_callback, self.cancel_callback = goal_cb, cancel_cb
        self.lock = threading.RLock()
        self.status_list: list[StatusTracker] = []
        self.last_cancel = rospy.Time()  # the latest stamp a cancel-before-time gave
        self.status_list_timeout = rospy.Duration()
        self.id_generator = GoalIDGenerator()
        self.goal_sub = self.cancel_sub = self.status_timer = None
        self.status_pub = self.result_pub = self.feedback_pub = None
        self.auto_start, self.started = auto_start, False
        if auto_start:
            rospy.logwarn("You've passed in true for auto_start to the python action server, "
                          "you should always pass in false to avoid race conditions.")
            self.start()

    def register_goal_callback(self, cb: Any) -> None:
        """Hand new goals to `cb(handle)` instead."""
        self.goal_callback = cb

    def register_cancel_callback(self, cancel_cb: Any) -> None:
        """Hand cancel requests to `cancel_cb(handle)` instead."""
        self.cancel_callback = cancel_cb

    def start(self) -> None:
        """Open the topics and start taking goals."""
        with self.lock:
            self.initialize()
            self.started = True
            self.publish_status()

    def stop(self) -> None:
        """Close the topics (goals still running are not ended)."""
        with self.lock:
            self.started = False
            if self.status_timer is not None:
                self.status_timer.shutdown()
            for endpoint in (self.goal_sub, self.cancel_sub, self.status_pub,
                             self.feedback_pub, self.result_pub):
                if endpoint is not None:  # (None before start)
                    endpoint.unregister()

    def initialize(self) -> None:
        """The publishers, subscribers and status timer, with the parameters they read."""
        ns = rospy.remap_name(self.ns)
        queue = S.queue_size(rospy.get_param("actionlib_server_pub_queue_size", PUB_QUEUE_SIZE),
                      PUB_QUEUE_SIZE)
        self.status_pub = rospy.Publisher(f"{ns}/status", GoalStatusArray, latch=True,
                                          queue_size=queue)
        self.result_pub = rospy.Publisher(f"{ns}/result", self.ActionResult, queue_size=queue)
        self.feedback_pub = rospy.Publisher(f"{ns}/feedback", self.ActionFeedback,
                                            queue_size=queue)
        queue = S.queue_size(rospy.get_param("actionlib_server_sub_queue_size", -1), None)
        self.goal_sub = rospy.Subscriber(f"{ns}/goal", self.ActionGoal,
                                         callback=self.internal_goal_callback, queue_size=queue)
        self.cancel_sub = rospy.Subscriber(f"{ns}/cancel", GoalID,
                                           callback=self.internal_cancel_callback,
                                           queue_size=queue)
        self.status_frequency = _status_frequency(ns)
        self.status_list_timeout = rospy.Duration(
            rospy.get_param(f"{ns}/status_list_timeout", STATUS_LIST_TIMEOUT))
        if self.status_frequency > 0.0:
            self.status_timer = rospy.Timer(rospy.Duration(1.0 / self.status_frequency),
                                            self.publish_status_async)

    # --- what comes in --------------------------------------------------------------------------
    def internal_goal_callback(self, goal: Any) -> None:
        """A goal came: a new one goes to the user's goal callback (or is canceled at once if a
        cancel-before-time covers it); a known one only answers a cancel that came first."""
        with self.lock:
            if not self.started:
                return
            for tracker in self.status_list:
                if tracker.status.goal_id.id == goal.goal_id.id:
                    if tracker.status.status == S.RECALLING:  # its cancel came before it
                        tracker.status.status = S.RECALLED
                        self.publish_result(tracker.status, self.ActionResultType())
                    if tracker.handle_tracker is None:
                        tracker.handle_destruction_time = rospy.Time.now()
                    return
            tracker = StatusTracker(None, None, goal)
            self.status_list.append(tracker)
            tracker.handle_tracker = HandleTrackerDeleter(self, tracker)
            handle = ServerGoalHandle(tracker, self, tracker.handle_tracker)
            stamp = goal.goal_id.stamp.to_nsec()
            if stamp != 0 and stamp <= self.last_cancel.to_nsec():
                handle.set_canceled(None, "This goal handle was canceled by the action server "
                                          "because its timestamp is before the timestamp of "
                                          "the last cancel request")
            else:
                self.goal_callback(handle)

    def internal_cancel_callback(self, goal_id: Any) -> None:
        """A cancel request: an empty id and zero stamp cancel every goal, an id its goal, a
        stamp every goal stamped at or before it. An id of no goal yet is kept RECALLING, so
        that its goal is recalled when it comes."""
        with self.lock:
            if not self.started:
                return
            found = False
            for tracker in list(self.status_list):
                if not _covers(goal_id, tracker.status.goal_id):
                    continue
                found = found or goal_id.id == tracker.status.goal_id.id
                if tracker.handle_tracker is None:
                    tracker.handle_tracker = HandleTrackerDeleter(self, tracker)
                    tracker.handle_destruction_time = rospy.Time.now()
                handle = ServerGoalHandle(tracker, self, tracker.handle_tracker)
                if handle.set_cancel_requested():
                    self.cancel_callback(handle)
            if goal_id.id != "" and not found:
                tracker = StatusTracker(goal_id, S.RECALLING)
                tracker.handle_destruction_time = rospy.Time.now()
                self.status_list.append(tracker)
            if goal_id.stamp.to_nsec() > self.last_cancel.to_nsec():
                self.last_cancel = goal_id.stamp

    # --- what goes out --------------------------------------------------------------------------
    def publish_result(self, status: Any, result: Any) -> None:
        """The goal's result on `<ns>/result`, then the status list."""
        with self.lock:
            _send(self.result_pub, self.ActionResult(status=status, result=result))
            self.publish_status()

    def publish_feedback(self, status: Any, feedback: Any) -> None:
        """A goal's feedback on `<ns>/feedback`, with its status."""
        with self.lock:
            _send(self.feedback_pub, self.ActionFeedback(status=status, feedback=feedback))

    def publish_status_async(self, event: Any) -> None:
        """The status timer's callback (nothing before start())."""
        with self.lock:
            if self.started:
                self.publish_status()

    def publish_status(self) -> None:
        """The status of every goal kept, dropping those ended more than the timeout ago."""
        with self.lock:
            now = rospy.Time.now()
            self.status_list = [tracker for tracker in self.status_list
                                if not _expired(tracker, self.status_list_timeout, now)]
            _send(self.status_pub,
                  GoalStatusArray(status_list=[tracker.status for tracker in self.status_list]),
                  now)


def _send(publisher: Any, message: Any, stamp: Any = None) -> None:
    """Publish the message stamped `stamp` (now, by default); nothing once rospy is shut
    down."""
    message.header.stamp = rospy.Time.now() if stamp is None else stamp
    if not rospy.is_shutdown():
        publisher.publish(message)


def _covers(cancel: Any, goal_id: Any) -> bool:
    """Whether the cancel request `cancel` (a GoalID) is for the goal `goal_id`. (Stamps are
    compared as numbers: a received one is a builtin_interfaces/Time, which has no order.)"""
    stamp = cancel.stamp.to_nsec()
    return cancel.id == "" and stamp == 0 or cancel.id == goal_id.id or \
        stamp != 0 and goal_id.stamp.to_nsec() <= stamp


def _expired(tracker: StatusTracker, timeout: Any, now: Any) -> bool:
    ended = tracker.handle_destruction_time
    return ended != rospy.Time() and ended + timeout < now


def _status_frequency(ns: str) -> float:
    """`<ns>/status_frequency` (deprecated), else the nearest `actionlib_status_frequency`."""
    if rospy.has_param(f"{ns}/status_frequency"):
        rospy.logwarn("You're using the deprecated status_frequency parameter, please switch "
                      "to actionlib_status_frequency.")
        return float(rospy.get_param(f"{ns}/status_frequency", STATUS_FREQUENCY))
    found = rospy.search_param("actionlib_status_frequency")
    return STATUS_FREQUENCY if found is None else float(rospy.get_param(found,
                                                                        STATUS_FREQUENCY))
