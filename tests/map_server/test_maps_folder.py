"""The maps shipped in maps/ load cleanly, and README.md describes each of them."""

import sys
from pathlib import Path

import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "catkin_ws" / "src" / "map_server" / "src"))
from map_server import map_io  # noqa: E402

MAPS = REPO / "maps"
YAMLS = sorted(MAPS.glob("*.yaml"))


@pytest.mark.parametrize("yaml_path", YAMLS, ids=[p.name for p in YAMLS])
def test_loads_without_warnings_and_is_documented(yaml_path):
    omap = map_io.load_map(yaml_path)
    assert omap.config.warnings == ()
    assert omap.width > 100 and omap.height > 100
    assert (omap.data == 100).any() and (omap.data == 0).any()
    readme = (MAPS / "README.md").read_text()
    assert f"`{yaml_path.name}`" in readme
    assert f"{omap.width} x {omap.height} cells" in readme


def solid_squares(mask, side):
    """How many side x side windows of `mask` are all True (a summed-area table)."""
    table = np.pad(mask.astype(np.int64).cumsum(0).cumsum(1), ((1, 0), (1, 0)))
    sums = table[side:, side:] - table[:-side, side:] - table[side:, :-side] + table[:-side, :-side]
    return int(np.count_nonzero(sums == side * side))


def axes_angle_deg(points, resolution):
    """The rotation (0..90 degrees) that lines the most wall cells up along x and y: walls
    along the axes pile their cells into few bins of a projection."""
    best, best_angle = -1.0, 0
    for angle in range(90):
        a = np.radians(angle)
        c, s = np.cos(a), np.sin(a)
        score = 0.0
        for proj in (c * points[:, 0] + s * points[:, 1], -s * points[:, 0] + c * points[:, 1]):
            bins = np.floor(proj / resolution).astype(np.int64)
            score += float(np.square(np.bincount(bins - bins.min())).sum())
        if score > best:
            best, best_angle = score, angle
    return best_angle


def test_willow_is_a_slam_map_like_the_books():
    """Chapter 9's willow map: made by SLAM (free, occupied and unknown cells), not
    axis-aligned, and with a big black blob painted over a room the robot must not enter."""
    willow = map_io.load_map(MAPS / "willow.yaml")
    assert "make_willow_map" in (MAPS / "willow.yaml").read_text()
    assert (MAPS / "willow.pgm").stat().st_size < 2_000_000
    cells = willow.data.size
    free, wall, unknown = ((willow.data == v).sum() / cells for v in (0, 100, -1))
    assert free > 0.1 and wall > 0.01 and unknown > 0.1, (free, wall, unknown)
    # The blob: walls a laser draws are a few cells thick; a painted room holds solid black
    # squares 2 m on a side.
    side = round(2.0 / willow.resolution)
    assert solid_squares(willow.data == 100, side) > 0
    # Not axis-aligned: the building's walls line up at an angle to the map's axes.
    rows, cols = np.nonzero(willow.data == 100)
    angle = axes_angle_deg(np.column_stack([cols, rows]) * willow.resolution, willow.resolution)
    assert 5 <= angle <= 85, angle


SHARED_WILLOW = REPO.parent / "shared" / "data" / "willow-full.pgm"


@pytest.mark.skipif(not SHARED_WILLOW.exists(), reason="shared willow-full.pgm not present")
def test_reads_a_real_gimp_made_pgm(tmp_path):
    """The Willow Garage plan from Stage's examples (read in place, never copied here)."""
    from PIL import Image

    (tmp_path / "willow.yaml").write_text(
        f"image: {SHARED_WILLOW}\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\n"
        "occupied_thresh: 0.65\nfree_thresh: 0.196\n"
    )
    omap = map_io.load_map(tmp_path / "willow.yaml")
    assert (omap.width, omap.height) == (540, 587)
    grey = np.asarray(Image.open(SHARED_WILLOW).convert("L"), dtype=np.float64)
    occ = (255.0 - grey[::-1]) / 255.0
    expected = np.where(occ > 0.65, 100, np.where(occ < 0.196, 0, -1))
    np.testing.assert_array_equal(omap.data, expected)
    assert (omap.data == 100).sum() > 5000 and (omap.data == 0).sum() > 100000
