import io

import numpy as np
import pytest
from explorer.map_message import MapFormatError, decode_occupancy_grid

nav_msgs = pytest.importorskip("nav_msgs.msg")


def serialized(width=4, height=3, data=None, frame="map"):
    grid = nav_msgs.OccupancyGrid()
    grid.header.frame_id = frame
    grid.header.stamp.secs, grid.header.stamp.nsecs = 12, 500000000
    grid.info.resolution = 0.05
    grid.info.width, grid.info.height = width, height
    grid.info.origin.position.x, grid.info.origin.position.y = -1.5, 2.0
    grid.info.origin.orientation.w = 1.0
    grid.data = data if data is not None else [-1, 0, 100, 50] * (width * height // 4)
    buffer = io.BytesIO()
    grid.serialize(buffer)
    return buffer.getvalue()


def test_decodes_what_rospy_serializes():
    raw = decode_occupancy_grid(serialized())
    assert raw.frame_id == "map" and raw.stamp == pytest.approx(12.5)
    assert (raw.width, raw.height, raw.resolution) == (4, 3, pytest.approx(0.05))
    assert raw.origin == pytest.approx((-1.5, 2.0, 0.0))
    assert raw.data.dtype == np.int8 and raw.data.shape == (3, 4)
    assert raw.data[0].tolist() == [-1, 0, 100, 50]


def test_truncated_or_inconsistent_messages_are_refused():
    good = serialized()
    with pytest.raises(MapFormatError):
        decode_occupancy_grid(good[:30])
    with pytest.raises(MapFormatError):
        decode_occupancy_grid(good[:-2])
    with pytest.raises(MapFormatError):
        decode_occupancy_grid(serialized(width=5, height=3, data=[0] * 12))
