"""sensor_msgs_py.point_cloud2: PointCloud2 messages to and from numpy, as ROS 2's module.

`read_points` gives a structured array of the fields asked for (a view on the message's
bytes where no NaNs are skipped and no points picked), `read_points_numpy` a plain array
(the fields must share a type), `read_points_list` named tuples; `create_cloud` and
`create_cloud_xyz32` build clouds. A cloud whose data does not hold width × height points of
point_step bytes, or whose fields run past point_step, is a clear error, not garbage.
"""

from __future__ import annotations

import sys
from collections import namedtuple
from collections.abc import Iterable, Sequence
from typing import Any

import numpy as np

DUMMY_FIELD_PREFIX = "unnamed_field"
# sensor_msgs/PointField datatypes → numpy
_DATATYPES = {1: np.dtype(np.int8), 2: np.dtype(np.uint8), 3: np.dtype(np.int16),
              4: np.dtype(np.uint16), 5: np.dtype(np.int32), 6: np.dtype(np.uint32),
              7: np.dtype(np.float32), 8: np.dtype(np.float64)}
_NAMES = {1: "INT8", 2: "UINT8", 3: "INT16", 4: "UINT16", 5: "INT32", 6: "UINT32",
          7: "FLOAT32", 8: "FLOAT64"}


class PointCloudError(ValueError):
    """A cloud whose layout does not hold together."""


def dtype_from_fields(fields: Iterable[Any], point_step: int | None = None) -> np.dtype:
    """The numpy structured dtype of a cloud's PointFields (unnamed fields get
    DUMMY_FIELD_PREFIX names), `point_step` bytes a point when given."""
    names, formats, offsets = [], [], []
    for i, field in enumerate(fields):
        if field.datatype not in _DATATYPES:
            raise PointCloudError(f"field '{field.name}': unknown PointField datatype "
                                  f"{field.datatype} (expected 1 to 8: "
                                  f"{', '.join(_NAMES.values())})")
        base = _DATATYPES[field.datatype]
        count = int(field.count) if field.count else 1
        names.append(field.name or f"{DUMMY_FIELD_PREFIX}_{i}")
        formats.append(base if count == 1 else np.dtype((base, count)))
        offsets.append(int(field.offset))
    spec: dict[str, Any] = {"names": names, "formats": formats, "offsets": offsets}
    if point_step is not None:
        spec["itemsize"] = int(point_step)
    try:
        return np.dtype(spec)
    except ValueError as exc:  # fields past point_step, or overlapping
        raise PointCloudError(f"the fields do not fit point_step {point_step}: {exc}") \
            from None


def _points(cloud: Any) -> np.ndarray:
    dtype = dtype_from_fields(cloud.fields, cloud.point_step)
    expected = cloud.width * cloud.height * cloud.point_step
    data = cloud.data
    size = len(data) if not isinstance(data, np.ndarray) else data.nbytes
    if size != expected:
        raise PointCloudError(
            f"the cloud's data is {size} bytes, but width {cloud.width} × height "
            f"{cloud.height} × point_step {cloud.point_step} is {expected}: its fields or "
            "size do not match its data")
    if cloud.row_step and cloud.row_step != cloud.width * cloud.point_step:
        raise PointCloudError(f"row_step {cloud.row_step} is not width {cloud.width} × "
                              f"point_step {cloud.point_step}: rows with padding are not read")
    points = np.frombuffer(data, dtype=dtype)
    if bool(cloud.is_bigendian) != (sys.byteorder == "big"):
        points = points.byteswap().view(points.dtype.newbyteorder())
    return points


def read_points(cloud: Any, field_names: Sequence[str] | None = None, skip_nans: bool = False,
                uvs: Iterable[Any] | None = None,
                reshape_organized_cloud: bool = False) -> np.ndarray:
    """The cloud's points as a structured array: only `field_names` when given, the
    points at `uvs` (column, row) when given, those with a NaN dropped with `skip_nans`, and
    rows × columns with `reshape_organized_cloud`."""
    points = _points(cloud)
    if field_names is not None:
        missing = [n for n in field_names if n not in points.dtype.names]
        if missing:
            raise PointCloudError(f"the cloud has no field {', '.join(map(repr, missing))}; "
                                  f"its fields: {', '.join(points.dtype.names or ())}")
        points = points[list(field_names)]
    if uvs is not None:
        picked = [u + v * cloud.width for u, v in (uvs if not isinstance(uvs, np.ndarray)
                                                   else uvs.tolist())]
        points = points[np.asarray(picked, dtype=np.int64)]
    if skip_nans and not cloud.is_dense:
        keep = np.ones(len(points), dtype=bool)
        for name in points.dtype.names or ():
            column = points[name]
            if column.dtype.kind == "f":
                keep &= ~np.isnan(column) if column.ndim == 1 else \
                    ~np.isnan(column).any(axis=tuple(range(1, column.ndim)))
        points = points[keep]
    if reshape_organized_cloud and cloud.height > 1 and not skip_nans and uvs is None:
        points = points.reshape(cloud.height, cloud.width)
    return points


def read_points_numpy(cloud: Any, field_names: Sequence[str] | None = None,
                      skip_nans: bool = False, uvs: Iterable[Any] | None = None,
                      reshape_organized_cloud: bool = False) -> np.ndarray:
    """The cloud's points as a plain array, one column per field (the fields must be of
    one type)."""
    chosen = [f for f in cloud.fields if field_names is None or f.name in field_names]
    kinds = {f.datatype for f in chosen}
    if len(kinds) > 1:
        raise PointCloudError(f"read_points_numpy needs fields of one type; these have "
                              f"{', '.join(sorted(_NAMES.get(k, str(k)) for k in kinds))}")
    points = read_points(cloud, field_names, skip_nans, uvs, reshape_organized_cloud)
    base = _DATATYPES[next(iter(kinds))] if kinds else np.dtype(np.float32)
    names = list(points.dtype.names or ())
    if not names:
        return np.empty((len(points), 0), dtype=base)
    columns = [points[n].reshape(points.shape + (-1,)) for n in names]
    return np.concatenate(columns, axis=-1).astype(base, copy=False)


def read_points_list(cloud: Any, field_names: Sequence[str] | None = None,
                     skip_nans: bool = False, uvs: Iterable[Any] | None = None) -> list[Any]:
    """The cloud's points as a list of namedtuples `Point(x=…, y=…, …)`."""
    points = read_points(cloud, field_names, skip_nans, uvs)
    Point = namedtuple("Point", points.dtype.names or ())  # noqa: PYI024 (rclpy's own)
    return [Point._make(p) for p in points.tolist()]


def create_cloud(header: Any, fields: Sequence[Any], points: Any) -> Any:
    """A PointCloud2 of `points` (a structured array, or rows of values) laid out by
    `fields`, one row high."""
    from sensor_msgs.msg import PointCloud2

    dtype = dtype_from_fields(fields)
    if isinstance(points, np.ndarray) and points.dtype.names is not None:
        array = np.empty(len(points), dtype=dtype)
        for name in dtype.names or ():
            array[name] = points[name]
    else:
        rows = [tuple(p) for p in points]
        array = np.array(rows, dtype=dtype) if rows else np.empty(0, dtype=dtype)
    return PointCloud2(header=header, height=1, width=len(array), is_dense=False,
                       is_bigendian=sys.byteorder == "big", fields=list(fields),
                       point_step=dtype.itemsize, row_step=dtype.itemsize * len(array),
                       data=array.tobytes())


def create_cloud_xyz32(header: Any, points: Any) -> Any:
    """A PointCloud2 of (x, y, z) rows as three float32 fields."""
    from sensor_msgs.msg import PointField

    fields = [PointField(name=n, offset=4 * i, datatype=PointField.FLOAT32, count=1)
              for i, n in enumerate("xyz")]
    return create_cloud(header, fields, points)
