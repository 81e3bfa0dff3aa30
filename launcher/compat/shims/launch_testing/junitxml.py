"""launch_testing.junitxml (launcher.compat.testing)."""

from launcher.compat.testing.junitxml import (
    unittestCaseToXml,
    unittestResultsToXml,
    unittestResultToXml,
)

__all__ = ["unittestCaseToXml", "unittestResultToXml", "unittestResultsToXml"]
