"""sensor_msgs_py.point_cloud2, as ROS 2's: clouds to structured and plain numpy arrays and
back, NaNs skipped, points picked by (u, v), and a cloud whose layout does not hold together
refused with the sizes that disagree."""

from __future__ import annotations

import math

import numpy as np
import pytest

from launcher.compat import finder

finder.install()

from sensor_msgs.msg import PointCloud2, PointField  # noqa: E402
from sensor_msgs_py import point_cloud2  # noqa: E402
from std_msgs.msg import Header  # noqa: E402

XYZI = [PointField(name=n, offset=4 * i, datatype=PointField.FLOAT32, count=1)
        for i, n in enumerate(("x", "y", "z", "intensity"))]


def test_a_cloud_round_trips_through_numpy_and_lists():
    points = [(1.0, 2.0, 3.0, 0.5), (math.nan, 0.0, 0.0, 1.0), (4.0, 5.0, 6.0, 2.0)]
    cloud = point_cloud2.create_cloud(Header(frame_id="lidar"), XYZI, points)
    assert (cloud.width, cloud.height, cloud.point_step, cloud.row_step) == (3, 1, 16, 48)
    structured = point_cloud2.read_points(cloud)
    assert structured.dtype.names == ("x", "y", "z", "intensity")
    assert structured["z"].tolist() == [3.0, 0.0, 6.0]
    kept = point_cloud2.read_points(cloud, field_names=["x", "y", "z"], skip_nans=True)
    assert kept.tolist() == [(1.0, 2.0, 3.0), (4.0, 5.0, 6.0)]
    plain = point_cloud2.read_points_numpy(cloud, field_names=["x", "y", "z"], skip_nans=True)
    assert plain.shape == (2, 3) and plain.dtype == np.float32
    listed = point_cloud2.read_points_list(cloud, skip_nans=True)
    assert listed[1].x == 4.0 and listed[1].intensity == 2.0
    assert point_cloud2.read_points(cloud, uvs=[(2, 0)])["x"].tolist() == [4.0]
    xyz = point_cloud2.create_cloud_xyz32(Header(), np.array([[1, 2, 3]], dtype=np.float32))
    assert point_cloud2.read_points_numpy(xyz).tolist() == [[1.0, 2.0, 3.0]]


def test_an_organized_cloud_keeps_its_rows():
    cloud = point_cloud2.create_cloud_xyz32(Header(), [(i, 0, 0) for i in range(6)])
    cloud.height, cloud.width, cloud.row_step = 2, 3, 36
    assert point_cloud2.read_points(cloud, reshape_organized_cloud=True).shape == (2, 3)


def test_a_cloud_whose_fields_do_not_match_its_data_is_refused_with_the_sizes():
    cloud = point_cloud2.create_cloud(Header(), XYZI, [(1, 2, 3, 4), (5, 6, 7, 8)])
    short = PointCloud2(header=cloud.header, height=1, width=3, fields=XYZI, point_step=16,
                        row_step=48, data=bytes(cloud.data))
    with pytest.raises(ValueError, match=r"the cloud's data is 32 bytes, but width 3 × height "
                                         r"1 × point_step 16 is 48"):
        point_cloud2.read_points(short)
    squeezed = PointCloud2(header=cloud.header, height=1, width=2, fields=XYZI, point_step=8,
                           row_step=16, data=bytes(cloud.data)[:16])
    with pytest.raises(ValueError, match="the fields do not fit point_step 8"):
        point_cloud2.read_points(squeezed)
    with pytest.raises(ValueError, match="the cloud has no field 'rgb'; its fields: x, y, z"):
        point_cloud2.read_points(cloud, field_names=["rgb"])
