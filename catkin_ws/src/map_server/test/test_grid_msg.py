"""OccupancyMap <-> nav_msgs/OccupancyGrid: order, origin, yaw, serialisation (no master)."""

import io
import sys
from pathlib import Path

import numpy as np
import pytest

HERE = Path(__file__).resolve().parent
sys.path[:0] = [str(HERE), str(HERE.parent / "src")]
pytest.importorskip("nav_msgs.msg")
import rospy  # noqa: E402
from map_server import map_io  # noqa: E402
from map_server.grid_msg import from_occupancy_grid, to_occupancy_grid  # noqa: E402
from nav_msgs.msg import OccupancyGrid  # noqa: E402
from rospy.numpy_msg import numpy_msg  # noqa: E402


def sample():
    data = np.array([[100, 0, -1], [0, 0, 100]], dtype=np.int8)  # bottom row first
    return map_io.OccupancyMap(data, 0.05, (-2.0, 3.5, 0.7))


def test_message_fields():
    grid = to_occupancy_grid(sample(), "map", rospy.Time(12, 500))
    assert grid.header.frame_id == "map" and grid.header.stamp == rospy.Time(12, 500)
    assert (grid.info.width, grid.info.height) == (3, 2)
    assert grid.info.map_load_time == rospy.Time(12, 500)
    assert list(grid.data) == [100, 0, -1, 0, 0, 100]
    assert grid.info.origin.position.x == -2.0 and grid.info.origin.position.y == 3.5
    q = grid.info.origin.orientation
    assert (q.x, q.y, q.z, q.w) == pytest.approx((0, 0, np.sin(0.35), np.cos(0.35)))


def test_round_trip_through_serialisation():
    buffer = io.BytesIO()
    to_occupancy_grid(sample(), "map", rospy.Time(1)).serialize(buffer)
    for cls in (OccupancyGrid, numpy_msg(OccupancyGrid)):  # map_saver uses numpy_msg
        back = from_occupancy_grid(cls().deserialize(buffer.getvalue()))
        np.testing.assert_array_equal(back.data, sample().data)
        assert back.origin == pytest.approx((-2.0, 3.5, 0.7))
        assert back.resolution == pytest.approx(0.05)


def test_inconsistent_message_is_refused():
    grid = to_occupancy_grid(sample(), "map", rospy.Time(1))
    grid.data = grid.data[:-1]
    with pytest.raises(map_io.MapError, match="5 cells"):
        from_occupancy_grid(grid)
