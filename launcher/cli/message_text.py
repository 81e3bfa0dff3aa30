"""A message given on the command line as YAML, as ros2's verbs take it (`topic pub`,
`service call`, `action send_goal`)."""

from __future__ import annotations

from typing import Any

from launcher.errors import UsageError


def message_from(type_name: str, text: str, what: str) -> Any:
    """The `type_name` message that the YAML `text` gives; `what` (the message, the request,
    the goal) names it in the error when the text is not YAML."""
    import yaml

    from launcher.bus.messages import build

    try:
        values = yaml.safe_load(text)
    except yaml.YAMLError as exc:
        raise UsageError(f"the {what} is not valid YAML: {exc}") from None
    return build(type_name, values)
