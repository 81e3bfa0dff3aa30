"""A graph of its own for a test run: a private, temporary run folder (the graph's socket and
its peers' live there), this process and what it starts joining it; the user's run folder
is given back after."""

from __future__ import annotations

import os
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager

from launcher.bus.places import RUN_VARIABLE


@contextmanager
def own_graph(prefix: str) -> Iterator[str]:
    """The private run folder, while the block runs."""
    previous = os.environ.get(RUN_VARIABLE)
    with tempfile.TemporaryDirectory(prefix=prefix) as folder:
        os.environ[RUN_VARIABLE] = folder
        try:
            yield folder
        finally:
            if previous is None:
                os.environ.pop(RUN_VARIABLE, None)
            else:
                os.environ[RUN_VARIABLE] = previous
