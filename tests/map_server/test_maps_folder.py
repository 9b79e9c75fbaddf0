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


def test_willow_is_the_office_map():
    willow = map_io.load_map(MAPS / "willow.yaml")
    office = map_io.load_map(MAPS / "office.yaml")
    np.testing.assert_array_equal(willow.data, office.data)
    assert (willow.resolution, willow.origin) == (office.resolution, office.origin)


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
