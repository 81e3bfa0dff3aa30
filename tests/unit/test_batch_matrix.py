"""A batch's jobs: the matrix expanded, ids that stay, the command line's narrowing, and the
launch arguments each job's file must declare."""

from __future__ import annotations

from pathlib import Path

import pytest

from launcher.batch.checks import check_entries
from launcher.batch.matrix import MOST_JOBS, Overrides, expand, parse_only, select
from launcher.batch.resources import NodeOffer, parse_bytes, unmet
from launcher.batch.spec import BatchFile, Entry, Resources
from launcher.errors import Location, ParseError, UsageError


def batch(**fields) -> BatchFile:
    fields.setdefault("jobs", [Entry(test="drive_test.py")])
    return BatchFile(path=Path("demo.batch.yaml"), **fields)


def test_every_combination_seed_and_repeat_is_a_job():
    plans = expand(batch(matrix={"world": ["a", "b"], "speed": ["1", "2", "3"]},
                         seeds=[0, 1], repeats=2), Overrides())
    assert len(plans) == 2 * 3 * 2 * 2


def test_combinations_vary_fastest_so_the_table_fills_evenly():
    plans = expand(batch(matrix={"world": ["a", "b"]}, seeds=[0, 1]), Overrides())
    assert [(p.varied["world"], p.seed) for p in plans] == [("a", 0), ("b", 0), ("a", 1),
                                                          ("b", 1)]


def test_ids_are_the_same_in_a_second_expansion():
    first = [p.id for p in expand(batch(matrix={"w": ["a", "b"]}, seeds=[0, 1]), Overrides())]
    again = [p.id for p in expand(batch(matrix={"w": ["a", "b"]}, seeds=[0, 1]), Overrides())]
    assert first == again and len(set(first)) == 4


def test_an_edited_entry_makes_new_ids():
    before = expand(batch(), Overrides())[0].id
    after = expand(batch(jobs=[Entry(test="drive_test.py", arguments={"x": "1"})]),
                   Overrides())[0].id
    assert before != after


def test_an_entrys_matrix_key_wins_over_the_batchs():
    plans = expand(batch(matrix={"w": ["a", "b"]},
                         jobs=[Entry(test="t.py", matrix={"w": ["c"]})]), Overrides())
    assert [p.arguments["w"] for p in plans] == ["c"]


def test_a_fixed_argument_on_the_command_line_replaces_a_matrix_key():
    plans = expand(batch(matrix={"w": ["a", "b"]}), Overrides(fixed={"w": "z"}))
    assert [p.arguments["w"] for p in plans] == ["z"]


def test_matrix_on_the_command_line_adds_a_key():
    plans = expand(batch(matrix={"w": ["a"]}), Overrides(matrix={"speed": ["1", "2"]}))
    assert [p.varied for p in plans] == [{"w": "a", "speed": "1"}, {"w": "a", "speed": "2"}]


def test_too_many_jobs_are_refused_after_only_has_narrowed_them():
    plans = expand(batch(matrix={"a": [str(i) for i in range(MOST_JOBS)]}, seeds=[0, 1]),
                   Overrides())
    assert len(select(plans, parse_only(["seed=0"]))) == MOST_JOBS
    with pytest.raises(UsageError, match="at most 100,000"):
        select(plans, {})


def test_two_entries_of_one_file_are_different_jobs():
    plans = expand(batch(jobs=[Entry(test="t.py"), Entry(test="t.py", env={"A": "1"})]),
                   Overrides())
    assert len({p.id for p in plans}) == 2


def test_only_keeps_the_jobs_of_a_value():
    plans = expand(batch(matrix={"w": ["a", "b"]}, seeds=[0, 1]), Overrides())
    kept = select(plans, parse_only(["w=a", "seed=1"]))
    assert [(p.varied["w"], p.seed) for p in kept] == [("a", 1)]


def test_only_with_a_repeated_name_keeps_any_of_its_values():
    plans = expand(batch(seeds=[0, 1, 2]), Overrides())
    assert [p.seed for p in select(plans, parse_only(["seed=0", "seed=2"]))] == [0, 2]


def test_only_of_an_unknown_key_says_the_keys():
    plans = expand(batch(matrix={"world": ["a"]}), Overrides())
    with pytest.raises(UsageError, match=r"'wrold' is no matrix key \(did you mean 'world'"):
        select(plans, parse_only(["wrold=a"]))


def test_only_of_an_unknown_value_says_the_values():
    plans = expand(batch(matrix={"world": ["a", "b"]}), Overrides())
    with pytest.raises(UsageError, match=r"world=mars: not a value of world \(a, b\)"):
        select(plans, parse_only(["world=mars"]))


def test_rerun_keeps_only_those_ids():
    plans = expand(batch(seeds=[0, 1, 2]), Overrides())
    assert select(plans, {}, {plans[1].id}) == [plans[1]]


FACTS = {"kind": "test", "arguments": ["world_name", "speed"], "complete": True,
         "unresolved": []}


def test_a_matrix_key_that_is_no_launch_argument_is_refused_at_the_key():
    where = Location("demo.batch.yaml", 4, 3)
    b = batch(matrix={"wrold_name": ["a"]}, places={"matrix.wrold_name": where})
    with pytest.raises(ParseError) as caught:
        check_entries(b, Overrides(), [FACTS])
    assert str(caught.value) == (
        "demo.batch.yaml:4:3: 'wrold_name' is not a launch argument of drive_test.py (did you "
        "mean 'world_name'?); it takes: speed, world_name")


def test_a_key_a_file_may_declare_through_an_include_is_a_warning():
    facts = {**FACTS, "complete": False, "unresolved": ["include at x.yaml:3: not resolved"]}
    warnings = check_entries(batch(matrix={"other": ["a"]}), Overrides(), [facts])
    assert len(warnings) == 1 and "not resolved" in warnings[0]


def test_a_job_file_that_cannot_be_read_says_its_own_error_and_the_job():
    b = batch(jobs=[Entry(test="t.py", where=Location("demo.batch.yaml", 2, 5))])
    with pytest.raises(Exception, match=r"t.py:3:1: bad\n  \(job at demo.batch.yaml:2:5\)"):
        check_entries(b, Overrides(), [{"error": "t.py:3:1: bad"}])


@pytest.mark.parametrize(("text", "size"), [("512MiB", 512 * 2**20), ("2GiB", 2 * 2**30),
                                            ("2G", 2 * 10**9), ("1000", 1000)])
def test_sizes(text, size):
    assert parse_bytes(text, "memory") == size


NODES = [NodeOffer("10.0.0.1", 1, 0, 3 * 2**30, {"batch_head": 1000}),
         NodeOffer("10.0.0.2", 1, 0, 3 * 2**30, {})]


def test_a_request_a_node_can_meet():
    assert unmet(Resources(cpus=1, custom={"batch_head": 1}), NODES) is None


def test_a_gpu_no_node_has_is_said_with_what_each_node_has():
    why = unmet(Resources(gpus=1), NODES)
    assert why == ("each job asks for 1 CPU, 1 GPU; no node of the cluster can give that "
                   "(10.0.0.1: 1 CPU, "
                   "3.0 GiB, no GPU, 1000 batch_head; 10.0.0.2: 1 CPU, 3.0 GiB, no GPU)")


def test_more_cpus_than_any_one_node_has_is_unmet():
    assert unmet(Resources(cpus=2), NODES) is not None
