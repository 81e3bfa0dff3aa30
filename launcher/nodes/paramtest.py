"""rostest's `paramtest`: a `<test>` node that checks a parameter is set (and, given
`~param_value_expected`, to that value) within `~wait_time` seconds. Its private parameters,
as rostest's: `~param_name_target` (required), `~param_value_expected`, `~wait_time`
(default 20)."""

from __future__ import annotations

import time
import unittest

from launcher.nodes.rostest_node import run, start_node

NAME = "paramtest"


class ParamTest(unittest.TestCase):
    def test_param(self) -> None:
        import rospy

        target = start_node(self, NAME, "~param_name_target",
                            "paramtest needs the private parameter ~param_name_target")
        wait = float(rospy.get_param("~wait_time", 20.0))
        deadline = time.monotonic() + wait
        while not rospy.has_param(target) and time.monotonic() < deadline:
            time.sleep(0.1)
        self.assertTrue(rospy.has_param(target), f"parameter {target} was not set within "
                                                 f"{wait:g} s")
        if rospy.has_param("~param_value_expected"):
            expected = rospy.get_param("~param_value_expected")
            self.assertEqual(str(rospy.get_param(target)), str(expected),
                             f"parameter {target}")


def main(argv: list[str] | None = None) -> None:
    run(NAME, ParamTest, argv)


if __name__ == "__main__":
    main()
