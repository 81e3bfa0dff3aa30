"""The parts of launcher's rclpy that need no bus: time, durations, parameters, QoS, futures
and logging, with rclpy's semantics (expectations from ros2/rclpy's sources)."""

from __future__ import annotations

import pytest

from launcher.bus.qos import QoS
from launcher.compat import finder

finder.install()

import rclpy.logging  # noqa: E402
from rclpy.duration import Duration  # noqa: E402
from rclpy.parameter import Parameter  # noqa: E402
from rclpy.qos import (  # noqa: E402
    DurabilityPolicy,
    HistoryPolicy,
    QoSProfile,
    ReliabilityPolicy,
    qos_profile_sensor_data,
    to_launcher,
)
from rclpy.task import Future, Task  # noqa: E402
from rclpy.time import Time  # noqa: E402


def test_time_and_duration_arithmetic_and_messages():
    start = Time(seconds=1, nanoseconds=500)
    later = start + Duration(seconds=0.5)
    assert later.nanoseconds == 1_500_000_500
    assert later - start == Duration(nanoseconds=500_000_000)
    assert later > start and later.seconds_nanoseconds() == (1, 500_000_500)
    message = later.to_msg()
    assert (message.sec, message.nanosec) == (1, 500_000_500)
    assert Time.from_msg(message).nanoseconds == later.nanoseconds
    with pytest.raises(ValueError, match="Seconds value must not be negative"):
        Time(seconds=-1)
    with pytest.raises(TypeError):
        _ = start < 3


def test_parameters_type_themselves_and_refuse_a_mismatch():
    assert Parameter("a", value=3).type_ == Parameter.Type.INTEGER
    assert Parameter("b", value=[1.0, 2.0]).type_ == Parameter.Type.DOUBLE_ARRAY
    assert Parameter("c", Parameter.Type.STRING, "x").value == "x"
    with pytest.raises(ValueError, match="do not agree"):
        Parameter("d", Parameter.Type.INTEGER, "x")
    message = Parameter("e", value=True).to_parameter_msg()
    assert message.value.type == 1 and message.value.bool_value is True
    assert Parameter.from_parameter_msg(message).value is True


def test_qos_profiles_map_onto_launchers_qos():
    assert to_launcher(7) == QoS(depth=7)
    assert to_launcher(qos_profile_sensor_data) == QoS(depth=5, reliable=False)
    latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL,
                         reliability=ReliabilityPolicy.RELIABLE)
    assert to_launcher(latched) == QoS(depth=1, transient_local=True)
    assert to_launcher(QoSProfile(history=HistoryPolicy.KEEP_ALL)).depth == 1000
    with pytest.raises(Exception, match="History and/or depth settings are required"):
        QoSProfile()
    with pytest.raises(TypeError, match="Expected QoSProfile or int"):
        to_launcher("10")


def test_futures_and_tasks_run_coroutines_to_the_end():
    future = Future()
    seen = []
    future.add_done_callback(lambda f: seen.append(f.result()))

    async def wait() -> int:
        return await future + 1
    task = Task(wait)
    task()
    assert not task.done()
    future.set_result(41)
    assert seen == [41] and task.done() and task.result() == 42


def test_logging_layout_and_levels(capsys):
    logger = rclpy.logging.get_logger("talker")
    logger.info("hello")
    logger.debug("hidden")
    logger.set_level(rclpy.logging.LoggingSeverity.DEBUG)
    logger.get_child("part").debug("shown")
    for _ in range(2):
        logger.warning("once", once=True)
    out, err = capsys.readouterr()
    assert out == ""  # every level on stderr, as rcutils writes them
    assert err.startswith("[INFO] [") and err.splitlines()[0].endswith("] [talker]: hello")
    assert "hidden" not in err and "[talker.part]: shown" in err
    assert err.count("once") == 1 and "[WARN]" in err


def test_logging_goes_to_stdout_when_rcutils_is_told_so(capsys, monkeypatch):
    monkeypatch.setenv("RCUTILS_LOGGING_USE_STDOUT", "1")
    rclpy.logging.get_logger("talker").error("loud")
    out, err = capsys.readouterr()
    assert "[talker]: loud" in out and err == ""


def test_a_log_line_is_one_write_so_threads_never_run_lines_together(monkeypatch):
    """A multi-threaded executor's callbacks log at once: each line reaches the stream whole,
    its newline with it, as rcutils writes a line under its lock."""
    class Stream:
        def __init__(self) -> None:
            self.writes: list[str] = []

        def write(self, text: str) -> int:
            self.writes.append(text)
            return len(text)

        def flush(self) -> None:
            pass

    stream = Stream()
    monkeypatch.setattr("sys.stderr", stream)
    rclpy.logging.get_logger("server").info("Received cancel request")
    assert len(stream.writes) == 1 and stream.writes[0].endswith(
        "[server]: Received cancel request\n")


def test_rclpys_named_profiles_are_the_bus_vocabularys():
    import rclpy.qos

    from launcher.bus.qos import PROFILES

    for name in ("sensor_data", "parameters", "action_status_default", "rosout_default"):
        assert getattr(rclpy.qos, f"qos_profile_{name}").to_launcher() == PROFILES[name], name


def test_qos_compatibility_follows_rmws_rules():
    from rclpy.qos import LivelinessPolicy, QoSCompatibility, qos_check_compatible

    plain = QoSProfile(depth=10)
    assert qos_check_compatible(plain, plain) == (QoSCompatibility.OK, "")
    best_effort = QoSProfile(depth=10, reliability=ReliabilityPolicy.BEST_EFFORT)
    assert qos_check_compatible(best_effort, plain) == (
        QoSCompatibility.ERROR, "ERROR: Best effort publisher and reliable subscription;")
    latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL,
                         deadline=Duration(seconds=1))
    level, reason = qos_check_compatible(plain, latched)
    assert level == QoSCompatibility.ERROR and reason == (
        "ERROR: Volatile publisher and transient local subscription; "
        "ERROR: Subscription has a deadline, but publisher does not;")
    manual = QoSProfile(depth=10, liveliness=LivelinessPolicy.MANUAL_BY_TOPIC)
    assert qos_check_compatible(plain, manual) == (
        QoSCompatibility.WARNING,
        "WARNING: Publisher liveliness is SYSTEM_DEFAULT and subscription is MANUAL_BY_TOPIC;")
