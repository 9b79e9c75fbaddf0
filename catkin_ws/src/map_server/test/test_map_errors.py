"""Bad map files: each gets an exception naming the file and the problem."""

import os
import struct
import sys
import zlib
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
sys.path[:0] = [str(HERE), str(HERE.parent / "src")]  # no sourced workspace needed
from map_server import map_io, pgm  # noqa: E402
from map_server_fixtures import write_pgm_p5, write_yaml  # noqa: E402

GOOD = {
    "image": "m.pgm",
    "resolution": "0.05",
    "origin": "[0.0, 0.0, 0.0]",
    "negate": "0",
    "occupied_thresh": "0.65",
    "free_thresh": "0.196",
}


def yaml_with(tmp_path, drop=(), **changes):
    write_pgm_p5(tmp_path / "m.pgm", [[0, 254]])
    keys = {**GOOD, **changes}
    text = "".join(f"{k}: {v}\n" for k, v in keys.items() if k not in drop)
    path = tmp_path / "bad.yaml"
    path.write_text(text)
    return path


def test_missing_yaml_file(tmp_path):
    with pytest.raises(map_io.MapFileNotFoundError, match="nope.yaml: map YAML file not found"):
        map_io.load_map(tmp_path / "nope.yaml")
    with pytest.raises(FileNotFoundError):  # also a standard FileNotFoundError
        map_io.load_map(tmp_path / "nope.yaml")


def test_missing_image_names_the_resolved_path(tmp_path):
    path = write_yaml(tmp_path / "m.yaml", "gone.pgm")
    with pytest.raises(map_io.MapFileNotFoundError, match="gone.pgm: map image not found"):
        map_io.load_map(path)


def test_missing_keys_are_listed(tmp_path):
    path = yaml_with(tmp_path, drop=("resolution", "free_thresh"))
    with pytest.raises(map_io.MapYamlError, match="bad.yaml: missing key.*resolution, free_thresh"):
        map_io.load_map(path)


@pytest.mark.parametrize(
    "key, value, message",
    [
        ("resolution", "fast", "'resolution' must be a number"),
        ("resolution", "-0.05", "'resolution' must be positive"),
        ("resolution", "0", "'resolution' must be positive"),
        ("resolution", ".nan", "'resolution' must be finite"),
        ("resolution", "true", "'resolution' must be a number"),
        ("origin", "[1.0, 2.0]", "'origin' must be a list"),
        ("origin", "0.0", "'origin' must be a list"),
        ("origin", "[a, 0, 0]", "'origin' must be a number"),
        ("negate", "2", "'negate' must be 0 or 1"),
        ("occupied_thresh", "high", "'occupied_thresh' must be a number"),
        ("occupied_thresh", "1.5", "'occupied_thresh' must be between 0 and 1"),
        ("free_thresh", "-0.1", "'free_thresh' must be between 0 and 1"),
        ("free_thresh", "0.7", "free_thresh .* must be smaller than occupied_thresh"),
        ("image", "''", "'image' must be a file name"),
        ("image", "[a, b]", "'image' must be a file name"),
    ],
)
def test_bad_values(tmp_path, key, value, message):
    path = yaml_with(tmp_path, **{key: value})
    with pytest.raises(map_io.MapYamlError, match="bad.yaml: " + message):
        map_io.load_map(path)


def test_unknown_mode(tmp_path):
    path = yaml_with(tmp_path, mode="fancy")
    with pytest.raises(map_io.MapYamlError, match="unknown mode 'fancy'.*trinary, scale or raw"):
        map_io.load_map(path)


def test_not_yaml_at_all(tmp_path):
    path = tmp_path / "bad.yaml"
    path.write_text("image: [unclosed\n")
    with pytest.raises(map_io.MapYamlError, match="bad.yaml: not valid YAML"):
        map_io.load_map(path)
    path.write_text("just a sentence\n")
    with pytest.raises(map_io.MapYamlError, match="bad.yaml: expected a mapping"):
        map_io.load_map(path)
    path.write_text("")
    with pytest.raises(map_io.MapYamlError, match="expected a mapping"):
        map_io.load_map(path)


def test_image_given_instead_of_yaml(tmp_path):
    write_pgm_p5(tmp_path / "m.pgm", [[0, 255, 254]])
    with pytest.raises(map_io.MapYamlError, match="m.pgm"):
        map_io.load_map(tmp_path / "m.pgm")


def test_corrupt_images(tmp_path):
    (tmp_path / "m.png").write_bytes(b"\x89PNG\r\n\x1a\n" + b"garbage" * 10)
    with pytest.raises(map_io.MapImageError, match="m.png: corrupt or truncated"):
        map_io.load_map(write_yaml(tmp_path / "a.yaml", "m.png"))
    (tmp_path / "m.txt").write_text("hello")
    with pytest.raises(map_io.MapImageError, match="m.txt: not an image format"):
        map_io.load_map(write_yaml(tmp_path / "b.yaml", "m.txt"))
    (tmp_path / "t.pgm").write_bytes(b"P5\n4 4\n255\n" + bytes(5))
    with pytest.raises(map_io.MapImageError, match="t.pgm: corrupt PGM image: truncated"):
        map_io.load_map(write_yaml(tmp_path / "c.yaml", "t.pgm"))


@pytest.mark.parametrize(
    "data, message",
    [
        (b"P5\n", "header ends early"),
        (b"P5\n-3 2\n255\n", "width must be positive"),
        (b"P5\n2 x\n255\n", "height is not a number"),
        (b"P5\n1 1\n70000\n\x00\x00", "maxval 70000"),
        (b"P2\n2 1\n100\n5 200\n", "exceeds maxval"),
        (b"P2\n2 1\n255\n5 x\n", "non-number"),
        (b"P6\n1 1\n255\n\x00\x00\x00", "bad magic"),
    ],
)
def test_pgm_parser_errors(data, message):
    with pytest.raises(pgm.PgmError, match=message):
        pgm.parse_pgm(data)


def test_deprecated_form_checks_resolution(tmp_path):
    write_pgm_p5(tmp_path / "m.pgm", [[0]])
    with pytest.raises(map_io.MapYamlError, match="resolution must be positive"):
        map_io.load_image_map(tmp_path / "m.pgm", -1.0)


def test_deeply_nested_yaml_is_a_clear_error(tmp_path):
    from map_server.map_yaml import parse_map_yaml

    with pytest.raises(map_io.MapYamlError, match="nested too deeply"):
        parse_map_yaml("image: " + "[" * 5000 + "]" * 5000, tmp_path / "m.yaml")


@pytest.mark.parametrize(
    "key, value, message",
    [
        ("origin", "[0, 0, 1" + "0" * 400 + "]", "'origin' must be finite"),
        ("resolution", "1" + "0" * 400, "'resolution' must be finite"),
        ("resolution", "1.0e-320", "'resolution' 1e-320 does not fit MapMetaData's float32"),
        ("resolution", "1.0e+39", "'resolution' 1e\\+39 does not fit MapMetaData's float32"),
        ("image", '"a\\0b"', "'image' must be a file name"),
    ],
)
def test_values_python_cannot_use_as_given(tmp_path, key, value, message):
    path = yaml_with(tmp_path, **{key: value})
    with pytest.raises(map_io.MapYamlError, match="bad.yaml: " + message):
        map_io.load_map(path)


def test_exponent_without_a_dot_is_a_number_as_in_yaml_cpp(tmp_path):
    omap = map_io.load_map(yaml_with(tmp_path, resolution="5e-2", origin="[-1e1, 2E0, 0]"))
    assert omap.resolution == 0.05 and omap.origin == (-10.0, 2.0, 0.0)


def test_devices_and_pipes_are_refused_not_read(tmp_path):
    with pytest.raises(map_io.MapYamlError, match="/dev/zero: not a regular file"):
        map_io.load_map("/dev/zero")
    with pytest.raises(map_io.MapImageError, match="/dev/zero: not a regular file"):
        map_io.load_map(write_yaml(tmp_path / "z.yaml", "/dev/zero"))
    fifo = tmp_path / "pipe.yaml"
    os.mkfifo(fifo)
    with pytest.raises(map_io.MapYamlError, match="pipe.yaml: not a regular file"):
        map_io.load_map(fifo)


def test_png_declaring_a_huge_picture_is_refused(tmp_path):
    # A PNG declaring 20000 x 20000 pixels (PIL refuses more than 179 M) with no pixel data.
    def chunk(kind, data):
        return (
            struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
        )

    header = struct.pack(">IIBBBBB", 20000, 20000, 8, 0, 0, 0, 0)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", b"") + chunk(b"IEND", b"")
    (tmp_path / "bomb.png").write_bytes(png)
    with pytest.raises(map_io.MapImageError, match="bomb.png: too large for a map"):
        map_io.load_map(write_yaml(tmp_path / "b.yaml", "bomb.png"))


def test_a_key_given_twice_is_refused_naming_the_file_and_the_key(tmp_path):
    """PyYAML and yaml-cpp keep the last silently: a pasted `resolution:` would rescale it."""
    write_pgm_p5(tmp_path / "m.pgm", [[0, 254]])
    path = tmp_path / "twice.yaml"
    text = "".join(f"{k}: {v}\n" for k, v in GOOD.items()) + "resolution: 0.1\n"
    path.write_text(text)
    with pytest.raises(map_io.MapYamlError, match=r"twice.yaml: .*key 'resolution' given twice"):
        map_io.load_map(path)
