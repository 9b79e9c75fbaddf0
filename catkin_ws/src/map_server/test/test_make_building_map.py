"""The building-map generator is deterministic and draws what its docstring says."""

import importlib.machinery
import importlib.util
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path[:0] = [str(HERE), str(HERE.parent / "src")]  # no sourced workspace needed

from map_server import map_io  # noqa: E402

SCRIPT = HERE.parent / "scripts" / "make_building_map"


def load_script():
    loader = importlib.machinery.SourceFileLoader("make_building_map", str(SCRIPT))
    spec = importlib.util.spec_from_loader("make_building_map", loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


def cell(omap, x, y):
    row = int((y - omap.origin[1]) / omap.resolution)
    col = int((x - omap.origin[0]) / omap.resolution)
    return int(omap.data[row, col])


def test_same_bytes_every_time(tmp_path, capsys):
    script = load_script()
    script.main(["-f", str(tmp_path / "a")])
    script.main(["-f", str(tmp_path / "b")])
    assert "520 x 360" in capsys.readouterr().out
    assert (tmp_path / "a.pgm").read_bytes() == (tmp_path / "b.pgm").read_bytes()
    yaml_a = (tmp_path / "a.yaml").read_text().replace("a.pgm", "b.pgm")
    assert yaml_a == (tmp_path / "b.yaml").read_text()


def test_layout(tmp_path):
    load_script().main(["-f", str(tmp_path / "building")])
    omap = map_io.load_map(tmp_path / "building.yaml")
    assert (omap.width, omap.height, omap.resolution) == (520, 360, 0.05)
    assert omap.origin == (-13.0, -9.0, 0.0)
    assert cell(omap, 0.0, 0.0) == 0  # corridor
    assert cell(omap, 0.5, 1.0) == 100  # corridor wall
    assert cell(omap, -3.0, 1.0) == 0  # a door in it
    assert cell(omap, -3.0, 4.0) == 0  # a north room
    assert cell(omap, 9.0, 4.0) == -1  # the closed store room
    assert cell(omap, 0.0, -5.0) == 100  # meeting table
    assert cell(omap, -12.5, 0.0) == -1  # outside the building
    assert cell(omap, -12.0, -3.0) == 100  # west wall
