"""rosbag: ROS 1's rosbag Python API over rosbags (see rosbag.bag for what differs), with
launcher's rospy messages."""

from __future__ import annotations

from rosbag.bag import (  # noqa: F401
    Bag,
    Compression,
    ROSBagException,
    ROSBagFormatException,
    ROSBagUnindexedException,
)
from rosbag.rosbag_main import rosbagmain  # noqa: F401
