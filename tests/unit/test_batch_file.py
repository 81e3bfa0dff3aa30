"""The batch file: what it may say, and every mistake said at its place."""

from __future__ import annotations

from pathlib import Path

import pytest

from launcher.batch.load import load_batch
from launcher.errors import ParseError


def write(tmp_path: Path, text: str, files: tuple[str, ...] = ("drive_test.py",)) -> Path:
    for name in files:
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text("# a job file\n")
    path = tmp_path / "demo.batch.yaml"
    path.write_text(text)
    return path


def refused(tmp_path: Path, text: str) -> str:
    with pytest.raises(ParseError) as caught:
        load_batch(write(tmp_path, text))
    return str(caught.value).replace(str(tmp_path / "demo.batch.yaml"), "b")


def test_the_issues_shape_is_read(tmp_path):
    (tmp_path / "robot.launch.yaml").write_text("launch: []\n")
    batch = load_batch(write(tmp_path, """\
jobs:
  - test: drive_test.py
  - launch: robot.launch.yaml
    duration: 30
matrix:
  world: [empty.sdf, arena.sdf]
  speed: [0.5, 1.0]
seeds: 10
timeout: 120
retries: 1
resources: {cpus: 1}
"""))
    assert [e.kind for e in batch.jobs] == ["test", "launch"]
    assert batch.matrix == {"world": ["empty.sdf", "arena.sdf"], "speed": ["0.5", "1.0"]}
    assert batch.seeds == list(range(10))
    assert (batch.timeout, batch.retries, batch.resources.cpus) == (120, 1, 1)
    assert batch.jobs[1].duration == 30


def test_matrix_values_keep_the_text_as_written(tmp_path):
    batch = load_batch(write(tmp_path, "jobs:\n  - test: drive_test.py\n"
                                       "matrix:\n  speed: [0.50, 1]\n  on: [true]\n"))
    assert batch.matrix == {"speed": ["0.50", "1"], "on": ["true"]}


def test_seeds_as_a_list(tmp_path):
    batch = load_batch(write(tmp_path, "jobs:\n  - test: drive_test.py\nseeds: [3, 7]\n"))
    assert batch.seeds == [3, 7]


def test_the_name_defaults_to_the_files_stem(tmp_path):
    batch = load_batch(write(tmp_path, "jobs:\n  - test: drive_test.py\n"))
    assert batch.title == "demo"


def test_resources_with_a_size_and_custom_ones(tmp_path):
    batch = load_batch(write(tmp_path, "jobs:\n  - test: drive_test.py\nresources: "
                                       "{cpus: 0.5, memory: 2GiB, custom: {licence: 1}}\n"))
    assert batch.resources.memory == "2GiB"
    assert batch.resources.custom == {"licence": 1.0}


BAD = [
    ("unknown_job_file", "jobs:\n  - test: drive_tset.py\n",
     "b:2:11: test: 'drive_tset.py' does not exist (did you mean 'drive_test.py'?)"),
    ("empty_matrix", "jobs:\n  - test: drive_test.py\nmatrix: {}\n",
     "b:3:9: matrix: empty; give each key a list of values"),
    ("a_key_without_values", "jobs:\n  - test: drive_test.py\nmatrix:\n  world: []\n",
     "b:4:10: matrix: 'world' has no values; give it at least one"),
    ("seed_as_a_matrix_key", "jobs:\n  - test: drive_test.py\nmatrix:\n  seed: [1]\n",
     "b:4:3: matrix: 'seed' is the batch's own: use seeds: [0, 1, 2]"),
    ("unknown_key", "jobs:\n  - test: drive_test.py\nseed: 3\n",
     "b:3:1: unknown key 'seed' (did you mean 'seeds'?)"),
    ("negative_timeout", "jobs:\n  - test: drive_test.py\ntimeout: -1\n",
     "b:3:10: timeout: expected a number > 0, got -1"),
    ("lockstep_not_a_bool", "jobs:\n  - test: drive_test.py\nlockstep: maybe\n",
     "b:3:11: lockstep: expected true or false, got 'maybe'"),
    ("seeds_zero", "jobs:\n  - test: drive_test.py\nseeds: 0\n",
     "b:3:8: seeds: expected a whole number ≥ 1"),
    ("memory_in_words", "jobs:\n  - test: drive_test.py\nresources: {memory: lots}\n",
     "b:3:21: resources.memory: expected bytes or a size like 2GiB, got 'lots'"),
    ("rays_own_resource", "jobs:\n  - test: drive_test.py\nresources: {custom: {GPU: 1}}\n",
     "b:3:22: resources.custom: 'GPU' is Ray's own"),
    ("no_jobs", "matrix: {a: [1]}\n", "b:1:1: no `jobs:`"),
    ("empty_jobs", "jobs: []\n", "b:1:7: jobs: expected a list of jobs"),
    ("a_job_of_no_kind", "jobs:\n  - name: x\n", "b:2:5: jobs[1]: give one of test: FILE"),
    ("a_launch_without_its_end", "jobs:\n  - launch: drive_test.py\n",
     "b:2:5: jobs[1]: launch: drive_test.py needs one of duration, sim_duration or until"),
    ("two_ends", "jobs:\n  - launch: drive_test.py\n    duration: 3\n    until: x\n",
     "b:4:12: jobs[1]: duration and until both given; say one"),
    ("a_test_with_a_duration", "jobs:\n  - test: drive_test.py\n    duration: 3\n",
     "b:3:15: jobs[1]: duration is for launch jobs; a test ends itself"),
    ("wall_time_in_lockstep", "jobs:\n  - launch: drive_test.py\n    duration: 5\n"
     "lockstep: true\n", "b:3:15: jobs[1]: duration is wall time, which a lockstep run does "
     "not repeat; use sim_duration: 5"),
    ("timeout_inside_the_duration", "jobs:\n  - launch: drive_test.py\n    duration: 30\n"
     "    timeout: 20\n", "b:4:14: jobs[1]: timeout 20 is not longer than duration 30"),
    ("not_yaml", "jobs: [\n", "not valid YAML"),
    ("a_list_at_the_top", "- 1\n", "b:1:1: the batch file: expected a mapping"),
]


@pytest.mark.parametrize(("text", "said"), [b[1:] for b in BAD], ids=[b[0] for b in BAD])
def test_a_mistake_is_said_at_its_place(tmp_path, text, said):
    assert said in refused(tmp_path, text)


def test_a_batch_file_that_does_not_exist_is_said(tmp_path):
    with pytest.raises(ParseError, match="batch file '.*nope.yaml' does not exist"):
        load_batch(tmp_path / "nope.yaml")


def test_a_misspelt_absolute_job_file_is_said_with_the_file_beside_it(tmp_path):
    (tmp_path / "drive_test.py").write_text("#\n")
    said = refused(tmp_path, f"jobs:\n  - test: {tmp_path}/drive_tset.py\n")
    assert f"(did you mean '{tmp_path}/drive_test.py'" in said


def test_an_env_that_would_take_a_jobs_graph_is_refused(tmp_path):
    said = refused(tmp_path, "jobs:\n  - test: drive_test.py\nenv: {LAUNCHER_RUN_DIR: /x}\n")
    assert said.startswith("b:3:7: env: LAUNCHER_RUN_DIR is each job's own")
