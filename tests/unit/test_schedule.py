"""The one grid on which the sim's periodic systems and sensors run (sim/schedule.py)."""

import math
from types import SimpleNamespace

from launcher.sim import schedule

STEP = 0.001


def runs(rate: float, seconds: float, stall_at: float | None = None) -> list[float]:
    """The sim times at which work of `rate` runs, stepping as the sim does (its post_step when
    due); `stall_at`: one step there lasts 0.5 s (a slow step of a loaded machine)."""
    times, now, work = [], 0.0, SimpleNamespace(next_update=0.0)
    while now < seconds - 1e-12:
        now += 0.5 if stall_at is not None and abs(now - stall_at) < STEP / 2 else STEP
        if schedule.tick(work, now, rate):
            times.append(now)
    return times


def test_a_rate_that_is_no_multiple_of_the_step_keeps_its_average():
    assert len(runs(30.0, 10.0)) in (300, 301)  # adding 1/30 to each late step gave 294


def test_a_stall_restarts_the_grid_instead_of_catching_up_in_a_burst():
    times = runs(100.0, 2.0, stall_at=1.0)
    after = [t for t in times if t > 1.0]
    gaps = [b - a for a, b in zip(after, after[1:], strict=False)]
    assert min(gaps) > 0.009


def test_a_rate_of_zero_runs_every_step():
    assert len(runs(0.0, 0.1)) == 100


def test_an_infinite_period_never_comes():
    assert schedule.following(0.0, 1.0, math.inf) == math.inf


def test_idle_work_looks_again_after_the_lazy_look_at_least():
    assert schedule.idle(2.0, 0.001) == 2.0 + schedule.LAZY_LOOK
    assert schedule.idle(2.0, 1.0) == 3.0


def test_a_sensor_with_nobody_to_serve_looks_again_later_and_keeps_no_grid():
    sensor = SimpleNamespace(next_update=0.0)
    assert not schedule.serve(sensor, 1.0, 0.01, wanted=False)
    assert sensor.next_update == 1.0 + schedule.LAZY_LOOK
    assert schedule.serve(sensor, 1.05, 0.01, wanted=True)
    assert abs(sensor.next_update - 1.06) < 1e-9
