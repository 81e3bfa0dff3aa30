"""ROS 1's actionlib for rospy, as the actionlib tutorials use it: a package's
action/Fibonacci.action made into FibonacciAction & co. with no build step, a
SimpleActionServer with an execute callback, a SimpleActionClient sending a goal and
waiting, feedback and result; a second goal preempting the first. Then the goal-handle layer
under them: an ActionServer whose goal and cancel callbacks move each goal by its
ServerGoalHandle, and an ActionClient following each goal by its ClientGoalHandle."""

from __future__ import annotations

import signal

import pytest

from tests.support.nodes import node_package

SERVER = """#!/usr/bin/env python
import rospy
import actionlib
from course_actions.msg import FibonacciAction, FibonacciFeedback, FibonacciResult


class FibonacciServer:
    def __init__(self, name):
        self._as = actionlib.SimpleActionServer(name, FibonacciAction,
                                                execute_cb=self.execute_cb, auto_start=False)
        self._as.start()

    def execute_cb(self, goal):
        feedback = FibonacciFeedback(sequence=[0, 1])
        rate = rospy.Rate(20)
        for i in range(1, goal.order):
            if self._as.is_preempt_requested() or rospy.is_shutdown():
                rospy.loginfo("fibonacci: Preempted")
                self._as.set_preempted()
                return
            feedback.sequence.append(feedback.sequence[i] + feedback.sequence[i - 1])
            self._as.publish_feedback(feedback)
            rate.sleep()
        rospy.loginfo("fibonacci: Succeeded")
        self._as.set_succeeded(FibonacciResult(sequence=feedback.sequence))


rospy.init_node("fibonacci")
FibonacciServer(rospy.get_name())
print("serving", flush=True)
rospy.spin()
"""

CLIENT = """#!/usr/bin/env python
import rospy
import actionlib
from actionlib_msgs.msg import GoalStatus
from course_actions.msg import FibonacciAction, FibonacciGoal

rospy.init_node("fibonacci_client")
client = actionlib.SimpleActionClient("fibonacci", FibonacciAction)
print("server", client.wait_for_server(rospy.Duration(20)), flush=True)
heard = []
client.send_goal(FibonacciGoal(order=5), feedback_cb=lambda f: heard.append(list(f.sequence)))
print("finished", client.wait_for_result(rospy.Duration(20)), flush=True)
print("result", list(client.get_result().sequence), client.get_state() == GoalStatus.SUCCEEDED)
print("feedback", heard[-1] if heard else None)
client.send_goal(FibonacciGoal(order=200))
rospy.sleep(0.5)
client.send_goal(FibonacciGoal(order=3))  # preempts the long one
client.wait_for_result(rospy.Duration(20))
print("second", list(client.get_result().sequence))
"""

ACTION = """# the order of the sequence
int32 order
---
int32[] sequence
---
int32[] sequence
"""


def test_a_rospy_simple_action_server_and_client_as_the_tutorials_write_them(ws):
    ws.own_bus()
    package = node_package(ws, "course_actions", {"server.py": SERVER, "client.py": CLIENT})
    (package / "action").mkdir()
    (package / "action" / "Fibonacci.action").write_text(ACTION)
    server = ws.start("run", "course_actions", "server.py", output="server.txt")
    try:
        ws.wait_for_output("serving", 30, "server.txt")
        done = ws.run("run", "course_actions", "client.py", timeout=90)
        assert done.returncode == 0, done.stderr
        out = done.stdout
        assert "server True" in out and "finished True" in out, out
        assert "result [0, 1, 1, 2, 3, 5] True" in out, out
        assert "feedback [0, 1, 1, 2, 3, 5]" in out, out
        assert "second [0, 1, 1, 2]" in out, out
        said = ws.wait_for_output("fibonacci: Preempted", 30, "server.txt")
        assert said.count("fibonacci: Succeeded") >= 2, said
    finally:
        server.send_signal(signal.SIGINT)
        server.wait(20)


GOAL_SERVER = """#!/usr/bin/env python
import threading
import rospy
import actionlib
from actionlib_msgs.msg import GoalStatus
from course_actions.msg import FibonacciAction, FibonacciFeedback, FibonacciResult


def compute(gh, order):
    sequence = [0, 1]
    for i in range(1, order):
        sequence.append(sequence[i] + sequence[i - 1])
        gh.publish_feedback(FibonacciFeedback(sequence=sequence))
        rospy.sleep(0.05)
    gh.set_succeeded(FibonacciResult(sequence=sequence), "computed")


def on_goal(gh):
    order = gh.get_goal().order
    if order < 0:
        gh.set_rejected(text="negative order")
    elif order == 0:
        gh.set_accepted()
        gh.set_aborted(text="nothing to compute")
    elif order >= 100:
        gh.set_accepted("until canceled")
    elif order < 50:
        gh.set_accepted()
        threading.Thread(target=compute, args=(gh, order)).start()
    # (50 to 99: left pending)


def on_cancel(gh):
    print("cancel", GoalStatus.to_string(gh.get_goal_status().status), flush=True)
    gh.set_canceled(text="canceled on request")


rospy.init_node("fibonacci")
server = actionlib.ActionServer("fibonacci", FibonacciAction, on_goal, on_cancel,
                                auto_start=False)
server.start()
print("serving", flush=True)
rospy.spin()
"""

GOAL_CLIENT = """#!/usr/bin/env python
import sys
import threading
import time
import rospy
import actionlib
from actionlib import CommState
from actionlib_msgs.msg import GoalStatus
from course_actions.msg import FibonacciAction, FibonacciGoal

rospy.init_node("fibonacci_client")
client = actionlib.ActionClient("fibonacci", FibonacciAction)
print("server", client.wait_for_server(rospy.Duration(20)), flush=True)
moves, heard, done = [], [], threading.Event()


def on_transition(gh):
    moves.append(CommState.to_string(gh.get_comm_state()))
    if gh.get_comm_state() == CommState.DONE:
        done.set()


gh = client.send_goal(FibonacciGoal(order=int(sys.argv[1])), on_transition,
                      lambda gh, feedback: heard.append(list(feedback.sequence)))
if len(sys.argv) > 2:  # cancel once the goal is in that state
    deadline = time.monotonic() + 20
    while CommState.to_string(gh.get_comm_state()) != sys.argv[2] and time.monotonic() < deadline:
        time.sleep(0.01)
    gh.cancel()
print("done", done.wait(20))
print("moves", moves)
print("status", GoalStatus.to_string(gh.get_goal_status()), repr(gh.get_goal_status_text()))
print("terminal", GoalStatus.to_string(gh.get_terminal_state()))
print("result", list(gh.get_result().sequence))
print("feedback", heard)
"""


@pytest.fixture
def goal_server(ws):
    """An ActionServer with goal and cancel callbacks, and a function that runs the
    ActionClient with some arguments: its output and the server's."""
    ws.own_bus()
    package = node_package(ws, "course_actions", {"server.py": GOAL_SERVER,
                                                  "client.py": GOAL_CLIENT})
    (package / "action").mkdir()
    (package / "action" / "Fibonacci.action").write_text(ACTION)
    server = ws.start("run", "course_actions", "server.py", output="server.txt")

    def client(*args: str) -> tuple[str, str]:
        done = ws.run("run", "course_actions", "client.py", *args, timeout=90)
        assert done.returncode == 0, done.stderr
        assert "server True" in done.stdout and "done True" in done.stdout, done.stdout
        return done.stdout, ws.output("server.txt")

    try:
        ws.wait_for_output("serving", 30, "server.txt")
        yield client
    finally:
        server.send_signal(signal.SIGINT)
        server.wait(20)


def test_an_action_client_follows_an_accepted_goal_through_its_feedback_to_its_result(
        goal_server):
    out, _ = goal_server("5")
    assert "moves ['ACTIVE', 'WAITING_FOR_RESULT', 'DONE']" in out, out
    assert "status SUCCEEDED 'computed'" in out and "terminal SUCCEEDED" in out, out
    assert "result [0, 1, 1, 2, 3, 5]" in out, out
    assert "feedback [[0, 1, 1], [0, 1, 1, 2], [0, 1, 1, 2, 3], [0, 1, 1, 2, 3, 5]]" in out, out


def test_a_goal_the_server_rejects_ends_rejected_without_being_active(goal_server):
    out, _ = goal_server("-1")
    assert "moves ['PENDING', 'WAITING_FOR_RESULT', 'DONE']" in out, out
    assert "status REJECTED 'negative order'" in out and "result []" in out, out


def test_a_goal_the_server_aborts_ends_aborted_with_its_text(goal_server):
    out, _ = goal_server("0")
    assert "moves ['ACTIVE', 'WAITING_FOR_RESULT', 'DONE']" in out, out
    assert "status ABORTED 'nothing to compute'" in out and "terminal ABORTED" in out, out


def test_canceling_an_active_goal_preempts_it_through_the_servers_cancel_callback(
        goal_server):
    out, server = goal_server("100", "ACTIVE")
    assert "cancel PREEMPTING" in server, server
    assert "moves ['ACTIVE', 'WAITING_FOR_CANCEL_ACK', 'PREEMPTING', 'WAITING_FOR_RESULT', " \
        "'DONE']" in out, out
    assert "status PREEMPTED 'canceled on request'" in out, out


def test_canceling_a_pending_goal_recalls_it(goal_server):
    out, server = goal_server("50", "PENDING")
    assert "cancel RECALLING" in server, server
    assert "moves ['PENDING', 'WAITING_FOR_CANCEL_ACK', 'RECALLING', 'WAITING_FOR_RESULT', " \
        "'DONE']" in out, out
    assert "status RECALLED 'canceled on request'" in out, out


TF_BROADCASTER = """#!/usr/bin/env python
import rospy
import tf
import tf2_ros
from geometry_msgs.msg import TransformStamped

rospy.init_node("turtle_tf_broadcaster")
moving = tf.TransformBroadcaster()
static = tf2_ros.StaticTransformBroadcaster()
t = TransformStamped()
t.header.stamp = rospy.Time.now()
t.header.frame_id, t.child_frame_id = "base_link", "laser"
t.transform.translation.x, t.transform.rotation.w = 0.2, 1.0
static.sendTransform(t)
print("broadcasting", flush=True)
rate = rospy.Rate(20)
while not rospy.is_shutdown():
    moving.sendTransform((1.0, 2.0, 0.0), tf.transformations.quaternion_from_euler(0, 0, 1.5708),
                         rospy.Time.now(), "base_link", "world")
    rate.sleep()
"""

TF_LISTENER = """#!/usr/bin/env python
import rospy
import tf
import tf2_ros

rospy.init_node("turtle_tf_listener")
listener = tf.TransformListener()
listener.waitForTransform("world", "laser", rospy.Time(0), rospy.Duration(20))
(trans, rot) = listener.lookupTransform("world", "laser", rospy.Time(0))
print("tf", [round(v, 3) for v in trans], round(tf.transformations.euler_from_quaternion(rot)[2], 3))
buffer = tf2_ros.Buffer()
tf2_ros.TransformListener(buffer)
t = buffer.lookup_transform("world", "laser", rospy.Time(0), rospy.Duration(20))
print("tf2", round(t.transform.translation.x, 3), round(t.transform.translation.y, 3))
try:
    listener.lookupTransform("world", "gripper", rospy.Time(0))
except tf.LookupException as exc:
    print("lookup", exc)
"""


def test_rospys_tf_and_tf2_ros_as_ros_1_code_writes_them(ws):
    ws.own_bus()
    node_package(ws, "turtle_tf", {"broadcaster.py": TF_BROADCASTER,
                                   "listener.py": TF_LISTENER})
    broadcaster = ws.start("run", "turtle_tf", "broadcaster.py", output="broadcaster.txt")
    try:
        ws.wait_for_output("broadcasting", 30, "broadcaster.txt")
        done = ws.run("run", "turtle_tf", "listener.py", timeout=60)
        assert done.returncode == 0, done.stderr
        assert "tf [1.0, 2.2, 0.0] 1.571" in done.stdout, done.stdout
        assert "tf2 1.0 2.2" in done.stdout, done.stdout
        assert 'lookup "gripper" passed to lookupTransform argument source_frame does not ' \
               "exist." in done.stdout, done.stdout
    finally:
        broadcaster.send_signal(signal.SIGINT)
        broadcaster.wait(20)
