"""rclpy.subscription_content_filter_options."""

from __future__ import annotations

from typing import NamedTuple


class ContentFilterOptions(NamedTuple):
    """A subscription's content filter: a SQL-like expression and its `%n` parameters."""

    filter_expression: str
    expression_parameters: list[str]
