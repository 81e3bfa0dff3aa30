"""Cases where launcher still differs from the real tool and the difference is not yet fixed
(issue 39 is open while this list is not empty). Each is expected to fail, strictly: a case
that starts agreeing fails until it is taken off this list, so the list is always the truth.
A difference launcher keeps on purpose does not belong here but in choices.py, with its
reason. `python -m tests.fidelity.compare` prints the cases that differ now."""

from __future__ import annotations

KNOWN_DIFFERENCES: frozenset[str] = frozenset()
