"""launch.logging (launcher.api.logging)."""

from launcher.api.logging import (
    get_logger,
    get_output_loggers,
    handlers,
    launch_config,
    reset,
)

__all__ = ["get_logger", "get_output_loggers", "handlers", "launch_config", "reset"]


from launcher.compat.finder import rest_from_layout  # noqa: E402

__getattr__ = rest_from_layout(__name__)
