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
