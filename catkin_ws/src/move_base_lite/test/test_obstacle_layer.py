import math

import numpy as np
from explorer.grid import GridGeometry
from move_base_lite.obstacle_layer import ObstacleLayer, scan_endpoints


def test_hits_are_marked_and_a_later_beam_through_them_clears_them():
    layer = ObstacleLayer(GridGeometry(0.05, 0.0, 0.0, 100, 100), max_range=4.0)
    hits, free, origin = scan_endpoints([1.0, math.nan], 0.0, 0.1, 0.45, 8.0, (1.0, 2.5, 0.0))
    assert len(hits) == 1 and len(free) == 0
    layer.update(hits, free, origin)
    assert layer.marked[50, 40]  # (2.0, 2.5)
    hits, free, origin = scan_endpoints([math.inf], 0.0, 0.1, 0.45, 8.0, (1.0, 2.5, 0.0))
    layer.update(hits, free, origin)
    assert not layer.marked.any()
    assert np.isfinite(free).all()
