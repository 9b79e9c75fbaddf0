"""Loading maps: map_server's occupancy rule in every mode, formats, flip, origin."""

import sys
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

HERE = Path(__file__).resolve().parent
sys.path[:0] = [str(HERE), str(HERE.parent / "src")]  # no sourced workspace needed
from map_server import map_io  # noqa: E402
from map_server_fixtures import write_pgm_p5, write_yaml  # noqa: E402

# One row of probe values and what trinary mode makes of them with the book's
# thresholds (occ = (255 - v) / 255; > 0.65 occupied, < 0.196 free).
PROBE = [0, 40, 89, 90, 100, 204, 205, 206, 254, 255]
TRINARY = [100, 100, 100, -1, -1, -1, -1, 0, 0, 0]
# 89 -> occ 0.6510 (> 0.65); 90 -> 0.6471 (unknown); 205 -> 0.19608 (not < 0.196, unknown);
# 206 -> 0.19216 (free).


def load_probe(tmp_path, values=PROBE, **yaml_args):
    write_pgm_p5(tmp_path / "probe.pgm", [values])
    return map_io.load_map(write_yaml(tmp_path / "probe.yaml", "probe.pgm", **yaml_args))


def test_trinary_default_mode(tmp_path):
    omap = load_probe(tmp_path)
    assert omap.data.dtype == np.int8
    assert omap.data[0].tolist() == TRINARY
    assert omap.config.mode == "trinary"


def test_negate_reverses_the_meaning_of_grey(tmp_path):
    omap = load_probe(tmp_path, negate=1)
    # With negate, occ = v / 255: white is occupied, black is free.
    expected = [0, 0, -1, -1, -1, 100, 100, 100, 100, 100]
    assert omap.data[0].tolist() == expected


def test_custom_thresholds(tmp_path):
    omap = load_probe(tmp_path, occupied=0.9, free=0.5)
    # occ > 0.9 only for v < 25.5; occ < 0.5 for v > 127.5.
    assert omap.data[0].tolist() == [100, -1, -1, -1, -1, 0, 0, 0, 0, 0]


def test_scale_mode_is_linear_between_thresholds(tmp_path):
    omap = load_probe(tmp_path, values=[0, 128, 90, 205, 254], mode="scale")
    occ = (255 - 128) / 255
    expected_128 = int(1 + 98 * (occ - 0.196) / (0.65 - 0.196))
    assert expected_128 == 66
    cells = omap.data[0].tolist()
    assert cells[0] == 100 and cells[4] == 0
    assert cells[1] == expected_128
    assert cells[2] == 98  # just inside occupied_thresh: int(1 + 98 * 0.9935)
    assert cells[3] == 1  # just inside free_thresh
    assert all(1 <= c <= 99 for c in cells[1:4])


def test_raw_mode_copies_values(tmp_path):
    omap = load_probe(tmp_path, values=[0, 50, 100, 127, 255], mode="raw")
    # As in the original, 255 lands in an int8 cell as -1 (unknown).
    assert omap.data[0].tolist() == [0, 50, 100, 127, -1]
    negated = load_probe(tmp_path, values=[255, 205, 0], mode="raw", negate=1)
    assert negated.data[0].tolist() == [0, 50, -1]


def test_image_top_row_is_the_top_of_the_map(tmp_path):
    # 3 rows x 2 cols: top row black (occupied), bottom row white (free).
    write_pgm_p5(tmp_path / "m.pgm", [[0, 0], [205, 205], [254, 254]])
    omap = map_io.load_map(write_yaml(tmp_path / "m.yaml", "m.pgm"))
    assert (omap.width, omap.height) == (2, 3)
    # OccupancyGrid order: data[0] is the bottom row (y = origin y).
    assert omap.data.tolist() == [[0, 0], [-1, -1], [100, 100]]
    assert omap.flat().tolist() == [0, 0, -1, -1, 100, 100]


def test_resolution_and_origin(tmp_path):
    omap = load_probe(tmp_path, resolution=0.025, origin="[-100.0, -50.5, 0.3]")
    assert omap.resolution == pytest.approx(0.025)
    assert omap.origin == pytest.approx((-100.0, -50.5, 0.3))


def test_image_path_is_relative_to_the_yaml_folder(tmp_path, monkeypatch):
    (tmp_path / "maps" / "img").mkdir(parents=True)
    write_pgm_p5(tmp_path / "maps" / "img" / "m.pgm", [[0, 254]])
    yaml_path = write_yaml(tmp_path / "maps" / "m.yaml", "img/m.pgm")
    monkeypatch.chdir(tmp_path)
    assert map_io.load_map("maps/m.yaml").data.tolist() == [[100, 0]]
    absolute = write_yaml(tmp_path / "abs.yaml", str(tmp_path / "maps" / "img" / "m.pgm"))
    assert map_io.load_map(absolute).data.tolist() == [[100, 0]]
    assert map_io.load_map(yaml_path).config.image == tmp_path / "maps" / "img" / "m.pgm"


def test_plain_p2_pgm_with_comments(tmp_path):
    (tmp_path / "p2.pgm").write_text("P2\n# a comment\n3 1\n# another\n255\n0 205\n254\n")
    omap = map_io.load_map(write_yaml(tmp_path / "p2.yaml", "p2.pgm"))
    assert omap.data.tolist() == [[100, -1, 0]]


def test_16_bit_pgm_is_scaled_to_8_bit(tmp_path):
    values = np.array([[0, 52685, 65278]], dtype=">u2")  # 0, 205*257, 254*257
    (tmp_path / "w.pgm").write_bytes(b"P5 3 1 65535\n" + values.tobytes())
    omap = map_io.load_map(write_yaml(tmp_path / "w.yaml", "w.pgm"))
    assert omap.data.tolist() == [[100, -1, 0]]


def test_png_grey_and_16_bit(tmp_path):
    Image.fromarray(np.array([[0, 205, 254]], dtype=np.uint8)).save(tmp_path / "g.png")
    omap = map_io.load_map(write_yaml(tmp_path / "g.yaml", "g.png"))
    assert omap.data.tolist() == [[100, -1, 0]]
    wide = Image.fromarray(np.array([[0, 52685, 65278]], dtype=np.uint16))
    wide.save(tmp_path / "w.png")
    omap = map_io.load_map(write_yaml(tmp_path / "w.yaml", "w.png"))
    assert omap.data.tolist() == [[100, -1, 0]]


def test_colour_is_averaged_to_grey(tmp_path):
    rgb = np.array([[[255, 0, 0], [0, 255, 255], [254, 254, 254], [10, 20, 30]]], np.uint8)
    Image.fromarray(rgb, "RGB").save(tmp_path / "c.png")
    omap = map_io.load_map(write_yaml(tmp_path / "c.yaml", "c.png"))
    # means 85 (occ 0.667: occupied), 170 (0.333: unknown), 254 (free), 20 (occupied)
    assert omap.data.tolist() == [[100, -1, 0, 100]]


def test_transparent_pixels_are_unknown_in_trinary_and_scale(tmp_path):
    rgba = np.array(
        [[[0, 0, 0, 255], [0, 0, 0, 0], [255, 255, 255, 0], [254, 254, 254, 128]]], np.uint8
    )
    Image.fromarray(rgba, "RGBA").save(tmp_path / "a.png")
    trinary = map_io.load_map(write_yaml(tmp_path / "t.yaml", "a.png"))
    assert trinary.data.tolist() == [[100, -1, -1, 0]]
    scale = map_io.load_map(write_yaml(tmp_path / "s.yaml", "a.png", mode="scale"))
    assert scale.data.tolist() == [[100, -1, -1, 0]]
    raw = map_io.load_map(write_yaml(tmp_path / "r.yaml", "a.png", mode="raw"))
    assert raw.data.tolist() == [[0, 0, -1, -2]]  # alpha ignored: 255 -> -1, 254 -> -2


def test_jpg_blocks(tmp_path):
    # JPEG is lossy: use flat 8x8 blocks and far-from-threshold values.
    grey = np.full((16, 24), 254, dtype=np.uint8)
    grey[:, 8:16] = 0
    grey[:, 16:] = 205
    Image.fromarray(grey).save(tmp_path / "j.jpg", quality=95)
    omap = map_io.load_map(write_yaml(tmp_path / "j.yaml", "j.jpg"))
    assert (omap.width, omap.height) == (24, 16)
    assert omap.data[8, 3] == 0 and omap.data[8, 11] == 100 and omap.data[8, 20] == -1


def test_deprecated_image_and_resolution_form(tmp_path):
    write_pgm_p5(tmp_path / "m.pgm", [[0, 254]])
    omap = map_io.load_image_map(tmp_path / "m.pgm", 0.1)
    assert omap.data.tolist() == [[100, 0]]
    assert omap.resolution == 0.1 and omap.origin == (0.0, 0.0, 0.0)


def test_unknown_keys_are_warned_not_fatal(tmp_path):
    omap = load_probe(tmp_path, extra="colour: blue\n")
    assert omap.data[0].tolist() == TRINARY
    assert len(omap.config.warnings) == 1
    assert "colour" in omap.config.warnings[0] and "probe.yaml" in omap.config.warnings[0]


def test_negate_accepts_booleans(tmp_path):
    assert load_probe(tmp_path, negate="true").config.negate is True
    assert load_probe(tmp_path, negate="false").config.negate is False


def test_the_books_first_yaml_example(tmp_path):
    """Chapter 9's example: negate 1, so white (high values) is occupied."""
    write_pgm_p5(tmp_path / "map.pgm", [[255, 200, 100, 10]])
    (tmp_path / "map.yaml").write_text(
        "image: map.pgm\nresolution: 0.1\norigin: [0.0, 0.0, 0.0]\n"
        "occupied_thresh: 0.65\nfree_thresh: 0.196\nnegate: 1\n"
    )
    omap = map_io.load_map(tmp_path / "map.yaml")
    # p = v / 255: v > 165.75 (the book's 255 * 0.65) occupied, v < 49.98 free.
    assert omap.data.tolist() == [[100, 100, -1, 0]]
    assert omap.resolution == 0.1 and omap.config.warnings == ()
