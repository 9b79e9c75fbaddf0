"""Chapter 9's first look at a map: `rosrun map_server map_server willow.yaml`, then rviz
with a Map display on /map and fixed frame map (mapping.rviz).  No robot is running, so
only the map is drawn: its free and occupied cells must appear at rviz's scale (30 px/m)
in the numbers the PGM holds, placed where the YAML's origin puts them.  The book's map is
larger than mapping.rviz's 1280 x 800 window shows at that scale, so the test runs
mapping.rviz with its window grown to hold the whole map and its view centred on it."""

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


# Less than the 3D view measures in mapping.rviz's 1280 x 800 window (about 900 x 700; the
# docks take the rest): the window grows by what the map needs beyond it, no more, as a
# larger screen makes every screenshot slower.
DEFAULT_VIEW_PX = (800, 600)


def mapping_view_holding(meta, size_m, folder):
    """mapping.rviz, its window grown so the 3D view holds the whole map and its view
    centred on the map."""
    config = yaml.safe_load((rc.RVIZ / "mapping.rviz").read_text())
    centre = [meta["origin"][i] + size_m[i] / 2 for i in (0, 1)]
    view = config["Visualization Manager"]["Views"]["Current"]
    view["X"], view["Y"] = centre
    window = config["Window Geometry"]
    for key, metres, room in zip(("Width", "Height"), size_m, DEFAULT_VIEW_PX, strict=True):
        window[key] += max(0, int(np.ceil(metres * PX_PER_M)) - room)
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "mapping_whole_map.rviz"
    path.write_text(yaml.safe_dump(config, sort_keys=False))
    return path, (window["Width"], window["Height"]), centre


def test_map_server_map_in_the_mapping_view(ros):
    meta, free_cells, wall_cells, (width_m, height_m) = expected_cells(MAP_YAML)
    config, screen, centre = mapping_view_holding(
        meta, (width_m, height_m), ros.workdir / "rviz_config"
    )
    ros.start(["rosrun", "map_server", "map_server", str(MAP_YAML)], name="map_server")
    ros.wait_for_topic("/map")
    px_per_cell = (meta["resolution"] * PX_PER_M) ** 2
    want = {"free": free_cells * px_per_cell, "wall": wall_cells * px_per_cell}
    with rs.RvizSession(config, ros.env, ros.workdir / "rviz", screen=screen) as rviz:

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
    left = cx + (meta["origin"][0] - centre[0]) * PX_PER_M  # map x grows to the right
    bottom = cy - (meta["origin"][1] - centre[1]) * PX_PER_M  # and y upwards
    assert abs(xs.min() - left) < 4 and abs(ys.max() - bottom) < 4, what
