#!/usr/bin/env python3
"""The corpus's probe node: records, at its start, how the launch started it.

It writes one JSON file per start into $PROBE_OUT: its argv, its working folder, the
environment variables a launch sets (ROS_NAMESPACE, ROS_*, PROBE_*), the contents of every
parameter file it was given (ROS 2) and, for ROS 1, the whole parameter tree as the master
holds it when the node starts. A real roslaunch's master is asked over XML-RPC (as rosparam
does); under launcher, rospy is launcher's. Then it exits, or sleeps while PROBE_SLEEP says.
"""

import json
import os
import signal
import sys
import time


def parameter_files(argv):
    found = {}
    for flag, value in zip(argv, argv[1:], strict=False):
        if flag == "--params-file":
            try:
                with open(value, encoding="utf-8") as stream:
                    found[value] = stream.read()
            except OSError as error:
                found[value] = f"<unreadable: {error.strerror}>"
    return found


STOPPED = []  # the stop signal that came while the start was being recorded


def _stopped(signum, _frame):
    STOPPED.append(signum)
    raise KeyboardInterrupt  # (as Python's own handler: the probe ends by SIGINT)


def ros1_parameters():
    master = os.environ.get("ROS_MASTER_URI")
    if master:
        import xmlrpc.client
        code, message, value = xmlrpc.client.ServerProxy(master).getParam("/probe", "/")
        return value if code == 1 else {"<error>": message}
    import rospy
    rospy.init_node("probe", anonymous=True, disable_signals=True)
    return rospy.get_param("/")


def record_start():
    """Write the record of this start (the lifecycle probe's start too)."""
    argv = sys.argv[1:]
    record = {
        "argv": argv,
        "cwd": os.getcwd(),
        "env": {key: value for key, value in os.environ.items()
                if key.startswith(("ROS_", "PROBE_")) and key != "PROBE_OUT"},
        "parameter_files": parameter_files(argv),
    }
    if os.environ.get("PROBE_ROS1") == "1":
        try:
            record["parameters"] = ros1_parameters()
        except Exception as error:  # recorded, not raised: the record says what failed
            if STOPPED:  # a start cut short by the launch's end (numpy's import turns the
                raise KeyboardInterrupt from None  # interruption into an ImportError)
            record["parameters"] = {"<error>": repr(error)}
    out = os.environ["PROBE_OUT"]
    name = f"{time.monotonic_ns()}-{os.getpid()}.json"
    with open(os.path.join(out, name + ".part"), "w", encoding="utf-8") as stream:
        json.dump(record, stream, indent=1, sort_keys=True)
    os.rename(os.path.join(out, name + ".part"), os.path.join(out, name))


def main():
    signal.signal(signal.SIGINT, _stopped)
    record_start()
    time.sleep(float(os.environ.get("PROBE_SLEEP", "0")))
    sys.exit(int(os.environ.get("PROBE_EXIT", "0")))


if __name__ == "__main__":
    main()
