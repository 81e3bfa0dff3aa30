"""The one table of ROS 2 managed nodes' lifecycle (launcher/lifecycle.py): lifecycle_msgs'
ids and labels, the primary transitions from each state, and where a callback's return
takes a node, as rcl_lifecycle has them."""

from __future__ import annotations

import pytest

from launcher import lifecycle as lc
from launcher.machines import InvalidTransition


@pytest.mark.parametrize("state, labels", [
    (lc.UNCONFIGURED, ["configure", "shutdown"]),
    (lc.INACTIVE, ["cleanup", "activate", "shutdown"]),
    (lc.ACTIVE, ["deactivate", "shutdown"]),
    (lc.FINALIZED, []),
], ids=["unconfigured", "inactive", "active", "finalized"])
def test_each_primary_state_allows_its_transitions(state, labels):
    assert [t.label for t in lc.allowed(state)] == labels


def test_shutdown_by_label_is_the_one_that_starts_where_the_node_is():
    assert lc.labelled(lc.UNCONFIGURED, "shutdown").id == lc.UNCONFIGURED_SHUTDOWN
    assert lc.labelled(lc.INACTIVE, "shutdown").id == lc.INACTIVE_SHUTDOWN
    assert lc.labelled(lc.ACTIVE, "shutdown").id == lc.ACTIVE_SHUTDOWN
    assert lc.labelled(lc.ACTIVE, "configure") is None


def test_a_callbacks_return_moves_the_node_out_of_its_transition_state():
    assert lc.reached(lc.UNCONFIGURED, lc.CONFIGURE) == lc.INACTIVE
    assert lc.reached(lc.ACTIVE, lc.ACTIVE_SHUTDOWN) == lc.FINALIZED
    assert lc.MACHINE.move(lc.ACTIVATING, lc.FAILURE) == lc.INACTIVE
    assert lc.MACHINE.move(lc.CLEANINGUP, lc.ERROR) == lc.ERRORPROCESSING
    assert lc.MACHINE.move(lc.ERRORPROCESSING, lc.SUCCESS) == lc.UNCONFIGURED


def test_a_move_the_table_lacks_is_refused_in_rcl_lifecycles_words():
    with pytest.raises(InvalidTransition, match="No transition matching 3 found for current "
                                                "state unconfigured"):
        lc.reached(lc.UNCONFIGURED, lc.ACTIVATE)


def test_ids_labels_and_names_are_lifecycle_msgs():
    assert lc.STATES["errorprocessing"] == 15 and lc.LABELS[lc.SHUTTINGDOWN] == "shuttingdown"
    assert lc.NAMED == {"configure": 1, "cleanup": 2, "activate": 3, "deactivate": 4,
                        "unconfigured_shutdown": 5, "inactive_shutdown": 6,
                        "active_shutdown": 7}
