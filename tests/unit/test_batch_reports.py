"""A batch's reports over its records: the progress line, the table, JUnit, CSV and
matrix.png."""

import csv
import io
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from launcher.batch.csv_report import write_csv
from launcher.batch.junit_report import write_junit
from launcher.batch.matrix import Overrides, expand
from launcher.batch.picture import NO_MATPLOTLIB, write_matrix_png
from launcher.batch.progress import (
    CLEAR,
    Progress,
    ProgressState,
    render_finished,
    render_line,
    span,
)
from launcher.batch.results import JobResult, Status
from launcher.batch.spec import BatchFile, Entry
from launcher.batch.table import matrix_table, summary_line

BAR_LINE = ("[██████████░░░░░░░░░░] 21/40  passed 19  failed 1  errors 1  running 2  "
            "queued 17  ~1m05s left")


def make_batch(matrix=None, seeds=(0,), repeats=1, jobs=None):
    return BatchFile(jobs=jobs or [Entry(test="tests/drive_test.py")], matrix=matrix or {},
                     seeds=list(seeds), repeats=repeats, path=Path("demo.batch.yaml"))


def plans_of(batch):
    return expand(batch, Overrides())


def result(plan, status=Status.PASS, **fields):
    return JobResult(plan.id, status, **fields)


def all_pass(plans):
    return {p.id: result(p) for p in plans}


def halfway():
    """21 of 40 done (19 passed, 1 failed, 1 error), 2 running, 65 s to go."""
    return ProgressState(40, passed=19, failed=1, errors=1, running=2, elapsed=65 * 21 / 19)


# --- progress ---------------------------------------------------------------------------

def test_left_s_is_unknown_before_the_first_job_ends():
    assert ProgressState(40, running=4, elapsed=12.0).left_s is None


def test_left_s_is_remaining_times_elapsed_per_job():
    assert ProgressState(40, passed=10, elapsed=20.0).left_s == pytest.approx(60.0)


@pytest.mark.parametrize("seconds,text", [(3.24, "3.2s"), (42, "42s"), (65, "1m05s"),
                                          (161, "2m41s"), (7380, "2h03m")],
                         ids=["seconds-tenths", "seconds", "minutes", "minutes-2", "hours"])
def test_span(seconds, text):
    assert span(seconds) == text


def test_render_line_with_room_shows_the_whole_bar():
    assert render_line(halfway(), 120) == BAR_LINE


def test_render_line_shrinks_the_bar_first():
    line = render_line(halfway(), len(BAR_LINE) - 10)
    assert line.startswith("[█████░░░░░] 21/40")
    assert len(line) == len(BAR_LINE) - 10


def test_render_line_leaves_out_the_bar_then_counts_from_the_right():
    line = render_line(halfway(), 40)
    assert line == "21/40  passed 19  failed 1  errors 1"


def test_render_line_names_timeouts_and_cancelled_only_when_there_are_some():
    state = ProgressState(10, passed=5, timeouts=2, cancelled=1)
    assert "timeouts 2  cancelled 1" in render_line(state, 200)
    assert "timeouts" not in render_line(ProgressState(10, passed=5), 200)


@pytest.mark.parametrize("status,word", [(Status.FAIL, "FAIL"), (Status.ERROR, "ERROR"),
                                         (Status.TIMEOUT, "TIMEOUT"),
                                         (Status.CANCELLED, "CANCELLED")],
                         ids=lambda v: getattr(v, "value", v))
def test_render_finished_says_status_job_time_node_reason_and_log(status, word):
    plan = plans_of(make_batch({"world": ["world.sdf"]}, seeds=[7]))[0]
    done = result(plan, status, wall_s=11.23, node="10.0.0.2", reason="boom\nmore",
                  log="jobs/drive_test-abc/")
    assert render_finished(plan, done) == (f"{word}  drive_test[world=world.sdf, seed=7]  "
                                           "11.2 s  node 10.0.0.2: boom "
                                           "(log: jobs/drive_test-abc/)")


def test_render_finished_without_node_or_log():
    plan = plans_of(make_batch())[0]
    done = result(plan, Status.ERROR, wall_s=0.0, reason="not found")
    assert render_finished(plan, done) == "ERROR  drive_test[seed=0]  0.0 s  not found"


def test_interactive_progress_redraws_in_place():
    out = io.StringIO()
    Progress(out, interactive=True, width=120).update(halfway())
    assert out.getvalue() == CLEAR + BAR_LINE


def test_interactive_progress_prints_a_failure_above_the_bar():
    out, plan = io.StringIO(), plans_of(make_batch())[0]
    progress = Progress(out, interactive=True, width=120)
    progress.update(halfway())
    progress.finished(plan, result(plan, Status.FAIL, reason="boom"))
    assert out.getvalue().endswith(f"{CLEAR}FAIL  drive_test[seed=0]  0.0 s  boom\n{BAR_LINE}")


def test_interactive_progress_prints_nothing_for_a_pass():
    out, plan = io.StringIO(), plans_of(make_batch())[0]
    Progress(out, interactive=True, width=120).finished(plan, result(plan))
    assert out.getvalue() == ""


def test_close_ends_the_bars_line_once():
    out = io.StringIO()
    progress = Progress(out, interactive=True, width=120)
    progress.update(halfway())
    progress.close()
    progress.close()
    assert out.getvalue() == CLEAR + BAR_LINE + "\n"


def test_log_progress_prints_a_line_per_job():
    out, plan = io.StringIO(), plans_of(make_batch())[0]
    progress = Progress(out, interactive=False, clock=lambda: 0.0)
    progress.finished(plan, result(plan, wall_s=1.6))
    progress.finished(plan, result(plan, Status.TIMEOUT, wall_s=600.0, reason="past 600 s"))
    assert out.getvalue() == ("pass  drive_test[seed=0]  1.6 s\n"
                              "TIMEOUT  drive_test[seed=0]  600.0 s  past 600 s\n")


def test_log_progress_prints_a_summary_at_most_every_30_s():
    out, now = io.StringIO(), [0.0]
    progress = Progress(out, interactive=False, width=120, clock=lambda: now[0])
    for now[0] in (0.0, 10.0, 30.0, 45.0, 59.0, 61.0):
        progress.update(halfway())
    assert out.getvalue() == f"{BAR_LINE}\n{BAR_LINE}\n"


# --- the table ----------------------------------------------------------------------------

def statuses(plans, *pattern):
    """The results of `plans`, their statuses cycling through `pattern`."""
    return {p.id: result(p, pattern[i % len(pattern)]) for i, p in enumerate(plans)}


def test_table_with_two_keys_has_rows_and_columns():
    batch = make_batch({"world": ["a.sdf", "b.sdf"], "speed": ["1", "2"]}, seeds=[0, 1])
    plans = plans_of(batch)
    results = statuses(plans, Status.PASS, Status.PASS, Status.PASS, Status.FAIL)
    assert matrix_table(batch, plans, results) == (
        "drive_test (tests/drive_test.py)\n"
        "  world  speed=1  speed=2\n"
        "  a.sdf      2/2      2/2\n"
        "  b.sdf      2/2      0/2")


def test_table_with_one_key_has_rows():
    batch = make_batch({"world": ["a.sdf", "long_name.sdf"]})
    plans = plans_of(batch)
    assert matrix_table(batch, plans, all_pass(plans)) == (
        "drive_test (tests/drive_test.py)\n"
        "  world          passed/run\n"
        "  a.sdf                 1/1\n"
        "  long_name.sdf         1/1")


def test_table_without_keys_has_one_row():
    batch = make_batch(seeds=range(3), repeats=2)
    plans = plans_of(batch)
    assert matrix_table(batch, plans, all_pass(plans)).splitlines()[1:] == [
        "       passed/run", "  all         6/6"]


def test_table_with_three_keys_has_rows_of_all_but_the_last():
    batch = make_batch({"world": ["a", "b"], "speed": ["1", "2"], "light": ["on", "off"]})
    plans = plans_of(batch)
    assert matrix_table(batch, plans, all_pass(plans)).splitlines()[1:] == [
        "  world, speed  light=on  light=off",
        "  a, 1               1/1        1/1",
        "  a, 2               1/1        1/1",
        "  b, 1               1/1        1/1",
        "  b, 2               1/1        1/1"]


def test_table_counts_neither_cancelled_nor_unrun_jobs_as_run():
    batch = make_batch(seeds=range(4))
    plans = plans_of(batch)
    results = {plans[0].id: result(plans[0]), plans[1].id: result(plans[1], Status.FAIL),
               plans[2].id: result(plans[2], Status.CANCELLED)}
    assert matrix_table(batch, plans, results).splitlines()[-1].split() == ["all", "1/2"]


def test_table_has_one_block_per_entry_titled_by_label_and_file():
    entries = [Entry(test="tests/drive_test.py"),
               Entry(launch="launch/sim.launch.yaml", name="sim", matrix={"speed": ["1"]}),
               Entry(test="tests/left_out.py")]
    batch = make_batch({"world": ["a.sdf"]}, jobs=entries)
    plans = [p for p in plans_of(batch) if p.number != 2]  # as `--only job=…` leaves them
    blocks = matrix_table(batch, plans, all_pass(plans)).split("\n\n")
    assert [b.splitlines()[0] for b in blocks] == ["drive_test (tests/drive_test.py)",
                                                   "sim (launch/sim.launch.yaml)"]


def test_summary_line():
    plans = plans_of(make_batch(seeds=range(40)))
    results = statuses(plans, *[Status.PASS] * 38, Status.FAIL, Status.ERROR)
    assert summary_line(list(results.values()), 161.0, 2) == (
        "40 jobs: 38 passed, 1 failed, 1 error, 0 timed out, 0 cancelled in 2m41s "
        "(894 jobs/hour) on 2 nodes")


def test_summary_line_in_the_singular_and_without_time():
    plan = plans_of(make_batch())[0]
    assert summary_line([result(plan, Status.ERROR)], 0.0, 1) == (
        "1 job: 0 passed, 0 failed, 1 error, 0 timed out, 0 cancelled in 0.0s on 1 node")


# --- JUnit --------------------------------------------------------------------------------

@pytest.fixture
def mixed():
    """Six jobs: pass, fail, error, timeout, cancelled, and one not run."""
    batch = make_batch({"world": ["a.sdf", "b.sdf"]}, seeds=range(3))
    plans = plans_of(batch)
    kinds = [Status.PASS, Status.FAIL, Status.ERROR, Status.TIMEOUT, Status.CANCELLED]
    results = {p.id: result(p, s, wall_s=1.5, reason=f"{s.value} because",
                            node="10.0.0.2", log=f"jobs/{p.id}")
               for p, s in zip(plans, kinds, strict=False)}
    return batch, plans, results


def read_junit(tmp_path, plans, results, logs=None):
    write_junit(tmp_path / "junit.xml", "demo", plans, results, logs)
    return ET.parse(tmp_path / "junit.xml").getroot()


def test_junit_has_one_case_per_job_named_by_its_matrix(tmp_path, mixed):
    _, plans, results = mixed
    cases = read_junit(tmp_path, plans, results).findall("testsuite/testcase")
    assert [(c.get("classname"), c.get("name")) for c in cases[:2]] == [
        ("demo.drive_test", "[world=a.sdf, seed=0]"), ("demo.drive_test", "[world=b.sdf, seed=0]")]
    assert len(cases) == len(plans) == 6


def test_junit_suite_counts(tmp_path, mixed):
    _, plans, results = mixed
    suite = read_junit(tmp_path, plans, results).find("testsuite")
    assert {k: suite.get(k) for k in ("name", "tests", "failures", "errors", "skipped", "time")} \
        == {"name": "demo", "tests": "6", "failures": "1", "errors": "2", "skipped": "2",
            "time": "7.500"}


def test_junit_says_each_outcome(tmp_path, mixed):
    _, plans, results = mixed
    cases = read_junit(tmp_path, plans, results).findall("testsuite/testcase")
    said = [[(e.tag, e.get("message")) for e in c if e.tag != "properties"] for c in cases]
    assert said == [[], [("failure", "fail because")], [("error", "error because")],
                    [("error", "timeout because")], [("skipped", "cancelled")],
                    [("skipped", "not run")]]


def test_junit_properties(tmp_path, mixed):
    _, plans, results = mixed
    plan = plans[1]
    results[plan.id] = result(plan, Status.FAIL, node="10.0.0.2", sim_s=12.5, rtf=0.98,
                              state="9f2c")
    case = read_junit(tmp_path, plans, results).findall("testsuite/testcase")[1]
    found = {p.get("name"): p.get("value") for p in case.findall("properties/property")}
    assert found == {"world": "b.sdf", "seed": "0", "repeat": "0", "node": "10.0.0.2",
                     "sim_s": "12.5", "rtf": "0.98", "state": "9f2c"}


def test_junit_failure_lists_the_cases_that_did_not_pass(tmp_path, mixed):
    _, plans, results = mixed
    cases = [{"name": "test_drives", "status": "fail", "message": "AssertionError: 1 != 2"},
             {"name": "test_starts", "status": "pass", "message": ""}]
    results[plans[1].id] = result(plans[1], Status.FAIL, reason="1 case failed", cases=cases)
    case = read_junit(tmp_path, plans, results).findall("testsuite/testcase")[1]
    assert case.find("failure").text == "1 case failed\ntest_drives: fail: AssertionError: 1 != 2"


def test_junit_system_out_is_the_end_of_the_jobs_output(tmp_path, mixed):
    _, plans, results = mixed
    folder = tmp_path / "run" / results[plans[1].id].log
    folder.mkdir(parents=True)
    lines = [f"\x1b[31mline {i}\x1b[0m \x07\n" for i in range(300)]
    (folder / "output.log").write_text("".join(lines))
    cases = read_junit(tmp_path, plans, results, tmp_path / "run").findall("testsuite/testcase")
    out = cases[1].find("system-out").text.splitlines()
    assert (len(out), out[0], out[-1]) == (200, "line 100 ", "line 299 ")
    assert cases[2].find("system-out") is None  # no output.log there


# --- CSV ----------------------------------------------------------------------------------

def read_csv(tmp_path, plans, results):
    write_csv(tmp_path / "results.csv", plans, results)
    with (tmp_path / "results.csv").open(newline="") as file:
        return list(csv.reader(file))


def test_csv_columns_hold_every_matrix_key_in_order_first_seen(tmp_path):
    entries = [Entry(test="tests/drive_test.py", matrix={"speed": ["1"]}),
               Entry(launch="sim.launch.yaml", matrix={"light": ["on"]})]
    plans = plans_of(make_batch({"world": ["a.sdf"]}, jobs=entries))
    assert read_csv(tmp_path, plans, {})[0] == [
        "id", "job", "kind", "file", "world", "speed", "light", "seed", "repeat", "status",
        "reason", "node", "wall_s", "sim_s", "rtf", "state", "started", "log"]


def test_csv_row_of_a_job(tmp_path):
    plan = plans_of(make_batch({"world": ["a.sdf"]}, seeds=[3]))[0]
    done = result(plan, Status.FAIL, reason="boom", node="10.0.0.2", wall_s=11.25,
                  sim_s=30.0, started=1_800_000_000.0, log="jobs/drive_test-x")
    assert read_csv(tmp_path, [plan], {plan.id: done})[1] == [
        plan.id, "drive_test", "test", "tests/drive_test.py", "a.sdf", "3", "0", "fail", "boom",
        "10.0.0.2", "11.25", "30", "", "", "2027-01-15T08:00:00+00:00", "jobs/drive_test-x"]


def test_csv_row_of_a_job_not_run_leaves_its_outcome_empty(tmp_path):
    plan = plans_of(make_batch())[0]
    assert read_csv(tmp_path, [plan], {})[1] == [
        plan.id, "drive_test", "test", "tests/drive_test.py", "0", "0", *[""] * 9]


def test_csv_leaves_a_key_another_entry_lacks_empty(tmp_path):
    entries = [Entry(test="a.py", matrix={"speed": ["1"]}), Entry(test="b.py")]
    plans = plans_of(make_batch(jobs=entries))
    rows = read_csv(tmp_path, plans, all_pass(plans))
    assert [row[4] for row in rows] == ["speed", "1", ""]


# --- matrix.png ---------------------------------------------------------------------------

def test_matrix_png_is_drawn_side_by_side(tmp_path):
    pytest.importorskip("matplotlib")
    image_module = pytest.importorskip("PIL.Image")
    entries = [Entry(test="tests/drive_test.py"), Entry(launch="sim.launch.yaml")]
    batch = make_batch({"world": ["a.sdf", "b.sdf"], "speed": ["1", "2", "3"]}, jobs=entries)
    plans = plans_of(batch)
    results = statuses(plans, Status.PASS, Status.FAIL)
    assert write_matrix_png(tmp_path / "matrix.png", batch, plans, results) is None
    with image_module.open(tmp_path / "matrix.png") as image:
        assert image.format == "PNG"
        assert image.width > image.height > 100
        colours = {rgb for _, rgb in image.convert("RGB").getcolors(1 << 24)}
    assert any(r > g + 100 for r, g, _ in colours)  # a cell that failed: red
    assert any(g > r + 80 for r, g, _ in colours)  # a cell that passed: green


def test_matrix_png_without_matplotlib_says_how_to_get_it(tmp_path, monkeypatch):
    for name in ("matplotlib", "matplotlib.figure", "matplotlib.backends.backend_agg"):
        monkeypatch.setitem(sys.modules, name, None)
    batch = make_batch()
    plans = plans_of(batch)
    why = write_matrix_png(tmp_path / "matrix.png", batch, plans, all_pass(plans))
    assert why == NO_MATPLOTLIB == "matrix.png not drawn: pip install 'launcher[plot]'"
    assert not (tmp_path / "matrix.png").exists()
