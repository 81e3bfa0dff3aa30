"""ROS 1's actionlib for rospy, as the actionlib tutorials use it: a package's
action/Fibonacci.action made into FibonacciAction & co. with no build step, a
SimpleActionServer with an execute callback, a SimpleActionClient sending a goal and
waiting, feedback and result; a second goal preempting the first."""

from __future__ import annotations

import signal

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
