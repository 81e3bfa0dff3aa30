"""rostest's `publishtest`: a `<test>` node that checks topics are published (or, marked
`negative`, are not) within their timeouts. Its private parameter `~topics` is a list of
`{name: TOPIC, timeout: SECONDS, negative: false}`, as rostest's."""

from __future__ import annotations

import unittest

from launcher.nodes.rostest_node import published_type, run, start_node

NAME = "publishtest"


class PublishTest(unittest.TestCase):
    def test_publish(self) -> None:
        import rospy

        topics = start_node(self, NAME, "~topics", "publishtest needs the private parameter "
                            "~topics: a list of {name: TOPIC, timeout: SECONDS, negative: false}")
        for topic in topics:
            name, timeout = topic["name"], float(topic.get("timeout", 10.0))
            negative = bool(topic.get("negative", False))
            heard = published_type(rospy, name, timeout) is not None
            if negative:
                self.assertFalse(heard, f"{name} was published, and should not have been")
            else:
                self.assertTrue(heard, f"{name} was not published within {timeout:g} s")


def main(argv: list[str] | None = None) -> None:
    run(NAME, PublishTest, argv)


if __name__ == "__main__":
    main()
