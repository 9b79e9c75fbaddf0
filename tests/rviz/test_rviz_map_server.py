"""Chapter 9's first look at a map: `rosrun map_server map_server willow.yaml`, then rviz
with a Map display on /map and fixed frame map (mapping.rviz).  No robot is running, so
only the map is drawn: its free and occupied cells must appear at rviz's scale (30 px/m)
in the numbers the PGM holds, centred where the YAML's origin puts them."""

import sys
from pathlib import Path

import numpy as np
import yaml
from PIL import Image

sys.path.insert(0, str(Path(__file__).resolve().parent))

import rviz_checks as rc  # noqa: E402
from rviz_checks import rs  # noqa: E402

MAP_YAML = rc.REPO / "maps" / "willow.yaml"
PX_PER_M = 30.0  # mapping.rviz's TopDownOrtho scale


def expected_cells(yaml_path):
    """Free and occupied cell counts by map_server's trinary rule, and the map size (m)."""
    meta = yaml.safe_load(yaml_path.read_text())
    with Image.open(yaml_path.parent / meta["image"]) as image:
        pixels = np.asarray(image.convert("L"), dtype=np.float64)
    occupancy = (255.0 - pixels) / 255.0
    if meta.get("negate", 0):
        occupancy = pixels / 255.0
    free = int(np.count_nonzero(occupancy < meta["free_thresh"]))
    wall = int(np.count_nonzero(occupancy > meta["occupied_thresh"]))
    height, width = pixels.shape
    return meta, free, wall, (width * meta["resolution"], height * meta["resolution"])


def test_map_server_map_in_the_mapping_view(ros):
    meta, free_cells, wall_cells, (width_m, height_m) = expected_cells(MAP_YAML)
    ros.start(["rosrun", "map_server", "map_server", str(MAP_YAML)], name="map_server")
    ros.wait_for_topic("/map")
    px_per_cell = (meta["resolution"] * PX_PER_M) ** 2
    want = {"free": free_cells * px_per_cell, "wall": wall_cells * px_per_cell}
    with rs.RvizSession(rc.RVIZ / "mapping.rviz", ros.env, ros.workdir / "rviz") as rviz:

        def ready(img):
            counts = rc.measure(rviz, img)[2]
            return all(abs(counts[k] / v - 1) < 0.1 for k, v in want.items())

        path, img = rviz.settle(ready, timeout=30)
        view, masks, counts = rc.measure(rviz, img)
    what = f"screenshot {path}; pixel counts {counts}; want {want}"
    for name, pixels in want.items():
        assert abs(counts[name] / pixels - 1) < 0.1, f"{name} area: " + what
    # The drawn map spans width × height metres at 30 px/m, placed by the YAML origin.
    drawn = masks["free"] | masks["wall"]
    w, h = rs.extent(drawn)
    assert abs(w - width_m * PX_PER_M) < 6 and abs(h - height_m * PX_PER_M) < 6, what
    ys, xs = np.nonzero(drawn)
    cx, cy = rc.view_centre(view)
    left = cx + meta["origin"][0] * PX_PER_M  # map x grows to the right
    bottom = cy - meta["origin"][1] * PX_PER_M  # and y upwards
    assert abs(xs.min() - left) < 4 and abs(ys.max() - bottom) < 4, what
