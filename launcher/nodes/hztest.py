"""rostest's `hztest`: a `<test>` node that checks a topic's rate. Its private parameters, as
rostest's: `~topic` (required), `~hz` (the rate expected; 0: no message may come),
`~hzerror` (how far the rate may be from it), `~test_duration` (seconds of counting, default
5), `~wait_time` (seconds to wait for the first message, default 20). Its result goes where
rostest asked (`--gtest_output=xml:PATH`), as rostest.rosrun writes it."""

from __future__ import annotations

import time
import unittest

from launcher.nodes.rostest_node import published_type, run, start_node

NAME = "hztest"


class HzTest(unittest.TestCase):
    def test_hz(self) -> None:
        import rospy

        topic = start_node(self, NAME, "~topic", "hztest needs the private parameter ~topic")
        expected = float(rospy.get_param("~hz"))
        error = float(rospy.get_param("~hzerror", 0.0))
        duration = float(rospy.get_param("~test_duration", 5.0))
        wait = float(rospy.get_param("~wait_time", 20.0))
        stamps: list[float] = []
        kind = published_type(rospy, topic, wait if expected else duration)
        if kind is not None:
            rospy.Subscriber(topic, kind, lambda _m: stamps.append(time.monotonic()))
        if expected == 0:
            time.sleep(duration)
            self.assertFalse(stamps, f"{topic}: {len(stamps)} messages, expected none")
            return
        deadline = time.monotonic() + wait
        while not stamps and time.monotonic() < deadline:
            time.sleep(0.05)
        self.assertTrue(stamps, f"{topic}: no message within {wait:g} s")
        start = stamps[-1]
        time.sleep(duration)
        counted = [s for s in stamps if s > start]
        rate = len(counted) / duration
        self.assertLessEqual(abs(rate - expected), error,
                             f"{topic}: {rate:.2f} Hz, expected {expected:g} ± {error:g} Hz")


def main(argv: list[str] | None = None) -> None:
    run(NAME, HzTest, argv)


if __name__ == "__main__":
    main()
