"""launch.descriptions (launcher.api)."""

from launcher.api import Executable

__all__ = ["Executable"]


from launcher.compat.finder import rest_from_layout  # noqa: E402

__getattr__ = rest_from_layout(__name__)
