"""rostest's Python side over launcher: `rostest.rosrun(package, test_name, TestCase)`, what a
ROS 1 test node calls to run its unittest cases and write the results where rostest reads
them (`--gtest_output=xml:PATH` on its command line). A real rostest that the user installed
wins."""

from __future__ import annotations

import sys
import unittest
from pathlib import Path
from typing import Any

from launcher.compat.testing.junit import RESULTS_FLAG, RecordingResult, write

XML_OUTPUT_FLAG = RESULTS_FLAG  # (gtest's flag, which rostest took)


def results_file(argv: list[str]) -> Path | None:
    """Where rostest asked for the results (`--gtest_output=xml:PATH`), if it did."""
    for word in argv:
        if word.startswith(RESULTS_FLAG):
            return Path(word[len(RESULTS_FLAG):])
    return None


def rosrun(package: str, test_name: str, test: Any, sysargs: list[str] | None = None) -> None:
    """Run `test` (a TestCase class, or a suite), write its results for rostest, and exit
    with 0 when every case passed, else 1."""
    argv = sys.argv if sysargs is None else sysargs
    suite = unittest.TestLoader().loadTestsFromTestCase(test) if isinstance(test, type) \
        else test
    result = unittest.TextTestRunner(verbosity=2, resultclass=RecordingResult).run(suite)
    target = results_file(argv)
    if target is not None:
        write(target, f"{package}.{test_name}", [result])
    sys.exit(0 if result.wasSuccessful() else 1)


run = rosrun


def deprecated(func: Any) -> Any:
    """Decorate `func` to warn with DeprecationWarning when it is called."""
    def warned(*args: Any, **kwargs: Any) -> Any:
        import warnings

        warnings.warn(f"Call to deprecated function {func.__name__}.",
                      category=DeprecationWarning, stacklevel=2)
        return func(*args, **kwargs)
    warned.__name__, warned.__doc__ = func.__name__, func.__doc__
    warned.__dict__.update(func.__dict__)
    return warned


@deprecated
def unitrun(package: str, test_name: str, test: Any, sysargs: list[str] | None = None,
            coverage_packages: Any = None) -> None:
    """rosunit's unitrun: the same as rosrun, for a test run without a launch."""
    rosrun(package, test_name, test, sysargs)


def _declares(kind: str, topic: str, node_name: str) -> bool:
    """Whether the graph has `node_name` publishing (or subscribing to) `topic`, as this
    process's rospy node sees it; IOError when there is no node to ask with."""
    from rospy.core import state

    from launcher.bus import graph, keys

    if state.node is None:
        raise OSError("Unable to retrieve the graph's state: rospy.init_node() was not called")
    wanted = keys.PUBLISHER if kind == "publisher" else keys.SUBSCRIBER
    return any(e.kind == wanted and e.topic == topic and e.node_fqn == node_name
               for e in graph.entities(state.node.graph_session(), 0.5))


def is_subscriber(topic: str, subscriber_id: str) -> bool:
    """Whether node `subscriber_id` subscribes to `topic` (global names)."""
    return _declares("subscriber", topic, subscriber_id)


def is_publisher(topic: str, publisher_id: str) -> bool:
    """Whether node `publisher_id` publishes `topic` (global names)."""
    return _declares("publisher", topic, publisher_id)


def rostestmain() -> None:
    """The `rostest` command (rostest.rostest_main's)."""
    from rostest.rostest_main import rostestmain as main

    main()


__all__ = ["XML_OUTPUT_FLAG", "deprecated", "is_publisher", "is_subscriber", "rosrun",
           "rostestmain", "run", "unitrun"]
