"""`teleop_twist_keyboard`: keys to Twist on `cmd_vel`, as ROS 2's teleop_twist_keyboard.

Its keys (u i o j k l m , . and, shifted, the holonomic ones; t and b for z; q z w x e c for
the speed steps of 10%), parameters `stamped` (TwistStamped) and `frame_id`, its banner and
its "currently:" line. The terminal goes into raw mode for each key and is put back on every
way out (Ctrl-C, SIGTERM, an error); with no terminal on stdin it says how to give it one
instead of failing as ROS's does (termios.error)."""

from __future__ import annotations

import os
import select
import signal
import sys
from typing import Any

from launcher.bus.declarations import Param
from launcher.bus.node import Node
from launcher.errors import LaunchError, reported

PARAMETERS = (
    Param("stamped", "bool", False, "publish TwistStamped instead of Twist"),
    Param("frame_id", "string", "", "the TwistStamped's header.frame_id"),
)

BANNER = """
This node takes keypresses from the keyboard and publishes them
as Twist/TwistStamped messages. It works best with a US keyboard layout.
---------------------------
Moving around:
   u    i    o
   j    k    l
   m    ,    .

For Holonomic mode (strafing), hold down the shift key:
---------------------------
   U    I    O
   J    K    L
   M    <    >

t : up (+z)
b : down (-z)

anything else : stop

q/z : increase/decrease max speeds by 10%
w/x : increase/decrease only linear speed by 10%
e/c : increase/decrease only angular speed by 10%

CTRL-C to quit
"""
MOVES = {"i": (1, 0, 0, 0), "o": (1, 0, 0, -1), "j": (0, 0, 0, 1), "l": (0, 0, 0, -1),
         "u": (1, 0, 0, 1), ",": (-1, 0, 0, 0), ".": (-1, 0, 0, 1), "m": (-1, 0, 0, -1),
         "O": (1, -1, 0, 0), "I": (1, 0, 0, 0), "J": (0, 1, 0, 0), "L": (0, -1, 0, 0),
         "U": (1, 1, 0, 0), "<": (-1, 0, 0, 0), ">": (-1, -1, 0, 0), "M": (-1, 1, 0, 0),
         "t": (0, 0, 1, 0), "b": (0, 0, -1, 0)}
SPEEDS = {"q": (1.1, 1.1), "z": (0.9, 0.9), "w": (1.1, 1.0), "x": (0.9, 1.0),
          "e": (1.0, 1.1), "c": (1.0, 0.9)}


def _state(speed: float, turn: float) -> str:
    return f"currently:\tspeed {speed}\tturn {turn} "


class Terminal:
    """Raw mode for one key at a time; the settings it found are put back on every exit."""

    def __init__(self, fd: int) -> None:
        import termios

        self.fd, self.termios = fd, termios
        self.saved = termios.tcgetattr(fd)

    def key(self, timeout: float) -> str:
        import tty

        tty.setraw(self.fd)
        try:
            ready, _, _ = select.select([self.fd], [], [], timeout)
            return os.read(self.fd, 1).decode(errors="replace") if ready else ""
        finally:
            self.restore()

    def restore(self) -> None:
        self.termios.tcsetattr(self.fd, self.termios.TCSADRAIN, self.saved)


def run() -> int:
    if not os.isatty(sys.stdin.fileno()):
        raise LaunchError("teleop_twist_keyboard reads keys from a terminal, and its stdin is "
                          "not one: run it in a terminal of its own (`launcher run "
                          "teleop_twist_keyboard teleop_twist_keyboard`), or in a launch file "
                          "with prefix='xterm -e'")
    node = Node("teleop_twist_keyboard")
    terminal = Terminal(sys.stdin.fileno())
    previous = signal.signal(signal.SIGTERM, _interrupt)
    try:
        return _loop(node, terminal)
    except KeyboardInterrupt:
        return 0
    finally:
        terminal.restore()
        signal.signal(signal.SIGTERM, previous)
        node.destroy_node()


def _interrupt(signum: int, frame: Any) -> None:
    raise KeyboardInterrupt  # (SIGTERM ends it as Ctrl-C does: the terminal put back)


def _loop(node: Node, terminal: Terminal) -> int:
    parameters = node.params.declare(PARAMETERS)
    stamped, frame_id = parameters["stamped"], parameters["frame_id"]
    type_name = "geometry_msgs/msg/TwistStamped" if stamped else "geometry_msgs/msg/Twist"
    publisher = node.create_publisher(type_name, "cmd_vel")
    speed, turn = 0.5, 1.0
    x = y = z = th = 0.0
    status = 0
    print(BANNER, flush=True)
    print(_state(speed, turn), flush=True)
    while True:
        key = terminal.key(0.5)
        if key == "\x03":  # Ctrl-C in raw mode
            break
        if not key:
            continue
        if key in MOVES:
            x, y, z, th = MOVES[key]
        elif key in SPEEDS:
            speed, turn = speed * SPEEDS[key][0], turn * SPEEDS[key][1]
            print(_state(speed, turn), flush=True)
            if status == 14:
                print(BANNER, flush=True)
            status = (status + 1) % 15
        else:
            x = y = z = th = 0.0
        publisher.publish(_twist(node, stamped, frame_id, x * speed, y * speed, z * speed,
                                 th * turn))
    publisher.publish(_twist(node, stamped, frame_id, 0.0, 0.0, 0.0, 0.0))  # stop on the way out
    return 0


def _twist(node: Node, stamped: bool, frame_id: str, x: float, y: float, z: float,
           th: float) -> Any:
    twist = node.message("geometry_msgs/msg/Twist",
                         linear=node.message("geometry_msgs/msg/Vector3", x=x, y=y, z=z),
                         angular=node.message("geometry_msgs/msg/Vector3", x=0.0, y=0.0, z=th))
    if not stamped:
        return twist
    now = node.get_clock().now()
    sec, nanosec = divmod(int(getattr(now, "nanoseconds", 0)), 1_000_000_000)
    return node.message("geometry_msgs/msg/TwistStamped", twist=twist, header=node.message(
        "std_msgs/msg/Header", frame_id=frame_id,
        stamp=node.message("builtin_interfaces/msg/Time", sec=sec, nanosec=nanosec)))


def main() -> int:
    return reported(run, "teleop_twist_keyboard")


if __name__ == "__main__":
    sys.exit(main())
