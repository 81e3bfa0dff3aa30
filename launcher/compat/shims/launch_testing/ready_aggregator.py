"""launch_testing.ready_aggregator (launcher.compat.testing)."""

from launcher.compat.testing.ready_aggregator import ReadyAggregator

__all__ = ["ReadyAggregator"]
