"""`launcher bag` with the flags ros2 (and rosbag) users type: real nodes, real sessions, real
MCAP and SQLite files read back with rosbags."""

from __future__ import annotations

import subprocess
import time

import pytest
import yaml
from rosbags.rosbag2 import Reader

from tests.support.nodes import TALKER, script_launched
from tests.support.processes import launcher_argv


@pytest.fixture
def talking(ws):
    with script_launched(ws.own_bus(), "talker.py", TALKER, "talking", "3.0") as running:
        yield running


def metadata(folder) -> dict:
    return yaml.safe_load((folder / "metadata.yaml").read_text())["rosbag2_bagfile_information"]


def test_record_splits_keeps_qos_and_distro_and_ros1_options(talking):
    done = talking.run("bag", "record", "-a", "-s", "sqlite3", "-d", "0.5", "--duration",
                       "2.5", "-O", "trip.bag", timeout=60)
    assert done.returncode == 0, done.stderr
    assert "-O is ROS 1's rosbag option; a ROS 2 bag is a folder: writing 'trip/'" in done.stderr
    assert "--duration is ROS 1's rosbag option; recording stops after 2.5 s" in done.stderr
    info = metadata(talking.root / "trip")
    assert info["ros_distro"] == "jazzy" and info["storage_identifier"] == "sqlite3"
    files = info["relative_file_paths"]
    assert len(files) >= 3 and files[:2] == ["trip_0.db3", "trip_1.db3"]  # split each 0.5 s
    assert all((talking.root / "trip" / f).is_file() for f in files)
    topics = {t["topic_metadata"]["name"]: t for t in info["topics_with_message_count"]}
    latched = topics["/robot_description"]["topic_metadata"]["offered_qos_profiles"]
    assert [(q["reliability"], q["durability"], q["depth"]) for q in latched] == \
        [("reliable", "transient_local", 1)]
    plain = topics["/cmd_vel"]["topic_metadata"]["offered_qos_profiles"]
    assert [(q["reliability"], q["durability"]) for q in plain] == [("reliable", "volatile")]
    with Reader(talking.root / "trip") as reader:  # every file, in order
        stamps = [stamp for _, stamp, _ in reader.messages()]
        assert len(stamps) == info["message_count"] == sum(f["message_count"]
                                                          for f in info["files"])
        assert stamps == sorted(stamps)
    shown = talking.run("bag", "info", "trip").stdout
    assert "ROS Distro:        jazzy" in shown and "Storage id:        sqlite3" in shown
    sized = talking.run("bag", "record", "--topics", "/cmd_vel", "-o", "sized",
                        "--max-bag-size", "200", "--duration", "1.5", timeout=60)
    assert sized.returncode == 0, sized.stderr
    assert len(metadata(talking.root / "sized")["relative_file_paths"]) >= 2  # 48-byte Twists


def test_qos_overrides_file(talking):
    talking.write("qos.yaml", "/robot_description:\n  durability: volatile\n  depth: 1\n")
    done = talking.run("bag", "record", "/robot_description", "-o", "missed",
                       "--qos-profile-overrides-path", "qos.yaml", "--duration", "1.5")
    assert done.returncode == 0, done.stderr  # volatile: the latched message is not taken
    assert "recorded 0 messages on /robot_description" in done.stdout
    talking.write("bad.yaml", "/cmd_vel:\n  reliability: fast\n")
    bad = talking.run("bag", "record", "/cmd_vel", "-o", "never",
                      "--qos-profile-overrides-path", "bad.yaml")
    assert bad.returncode == 1 and "bad.yaml:1: QoS overrides: '/cmd_vel': reliability is " \
        "system_default, reliable, best_effort; got 'fast'" in bad.stderr, bad.stderr
    assert not (talking.root / "never").exists()
    talking.write("broken.yaml", "/cmd_vel: [1, 2\n")
    broken = talking.run("bag", "record", "/cmd_vel", "-o", "never",
                         "--qos-profile-overrides-path", "broken.yaml")
    assert broken.returncode == 1 and "broken.yaml:2:1: QoS overrides are not valid YAML" \
        in broken.stderr


def test_play_keeps_latched_topics_latched_and_takes_its_flags(talking):
    recorded = talking.run("bag", "record", "-a", "-o", "recorded", "--duration", "2", timeout=60)
    assert recorded.returncode == 0, recorded.stderr
    total = metadata(talking.root / "recorded")["message_count"]
    assert talking.run("bag", "list").stdout == "mcap\nsqlite3\n"
    player = subprocess.Popen(launcher_argv() + ["bag", "play", "recorded", "--clock", "20", "-r",
                                                 "0.5"], cwd=talking.root, env=talking.env,
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        time.sleep(1.5)  # the latched message went out at the start: a late reader gets it
        late = talking.run("topic", "echo", "/robot_description", "std_msgs/msg/String",
                           "--once", "--timeout", "5", "--qos-durability", "transient_local")
        assert late.returncode == 0 and "data: <robot name='r'/>" in late.stdout, late.stderr
        clock = talking.run("topic", "echo", "/clock", "--once", "--field", "clock.sec",
                            "--timeout", "5")
        assert clock.returncode == 0 and int(clock.stdout.split()[0]) > 1_000_000_000
    finally:
        out, err = player.communicate(timeout=60)
    assert player.returncode == 0 and f"played {total} messages" in out, err
    some = talking.run("bag", "play", "recorded", "--topics", "/cmd_vel", "--start-offset", "1",
                       "-r", "4", timeout=60)
    played = int(some.stdout.split("played ")[1].split()[0])
    assert 0 < played < total - 1
    unknown = talking.run("bag", "play", "recorded", "--topics", "/cmd_vle")
    assert unknown.returncode == 1 and "the bag has no topic /cmd_vle" in unknown.stderr
    paused = subprocess.Popen(launcher_argv() + ["bag", "play", "recorded", "-p", "-r", "8"],
                              cwd=talking.root, env=talking.env, stdin=subprocess.PIPE,
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    time.sleep(1.0)
    assert paused.poll() is None  # paused: nothing plays until a line comes on stdin
    out, err = paused.communicate("\n", timeout=60)
    assert "paused: press Enter to play" in out and f"played {total} messages" in out, err
