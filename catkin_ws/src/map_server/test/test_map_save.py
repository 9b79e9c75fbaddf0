"""Saving maps: map_saver's pixel rule, the book's YAML, round trips, atomic writes."""

import os
import sys
from pathlib import Path

import numpy as np
import pytest

HERE = Path(__file__).resolve().parent
sys.path[:0] = [str(HERE), str(HERE.parent / "src")]  # no sourced workspace needed

from map_server import map_io, pgm  # noqa: E402


def make_map(data, resolution=0.05, origin=(0.0, 0.0, 0.0)):
    return map_io.OccupancyMap(np.asarray(data, dtype=np.int8), resolution, origin)


def test_pixel_values_follow_map_saver(tmp_path):
    cells = [[-1, 0, 1, 64, 65, 100]]
    pgm_path, _ = map_io.save_map(tmp_path / "m", make_map(cells))
    pixels, maxval = pgm.read_pgm(pgm_path)
    assert maxval == 255
    assert pixels.tolist() == [[205, 254, 205, 205, 0, 0]]
    assert pgm_path.read_bytes().startswith(b"P5\n")


def test_occ_and_free_options(tmp_path):
    cells = [[-1, 0, 10, 11, 49, 50, 100]]
    pgm_path, _ = map_io.save_map(tmp_path / "m", make_map(cells), occupied=50, free=10)
    pixels, _ = pgm.read_pgm(pgm_path)
    assert pixels.tolist() == [[205, 254, 254, 205, 205, 0, 0]]


def test_bottom_row_of_the_map_is_the_last_image_row(tmp_path):
    pgm_path, _ = map_io.save_map(tmp_path / "m", make_map([[0, 0], [100, -1]]))
    pixels, _ = pgm.read_pgm(pgm_path)
    assert pixels.tolist() == [[0, 205], [254, 254]]


def test_yaml_is_the_books_format(tmp_path):
    omap = make_map([[0]], resolution=np.float32(0.05), origin=(-100.0, -100.0, -0.0))
    _, yaml_path = map_io.save_map(tmp_path / "map", omap)
    assert yaml_path.read_text() == (
        "image: map.pgm\n"
        "resolution: 0.050000\n"
        "origin: [-100.000000, -100.000000, 0.000000]\n"
        "negate: 0\n"
        "occupied_thresh: 0.65\n"
        "free_thresh: 0.196\n\n"
    )


def test_yaml_names_the_image_relative_to_itself(tmp_path):
    (tmp_path / "sub").mkdir()
    _, yaml_path = map_io.save_map(str(tmp_path / "sub" / "office.yaml"), make_map([[0]]))
    assert yaml_path == tmp_path / "sub" / "office.yaml"
    assert "image: office.pgm\n" in yaml_path.read_text()
    assert (tmp_path / "sub" / "office.pgm").exists()


def test_round_trip_is_cell_equal(tmp_path):
    rng = np.random.default_rng(7)
    data = rng.choice(np.array([-1, 0, 100], dtype=np.int8), size=(37, 53))
    omap = make_map(data, resolution=0.025, origin=(-3.25, 7.5, 0.5))
    _, yaml_path = map_io.save_map(tmp_path / "rt", omap)
    back = map_io.load_map(yaml_path)
    assert back.data.dtype == np.int8
    np.testing.assert_array_equal(back.data, data)
    assert back.resolution == pytest.approx(0.025)
    assert back.origin == pytest.approx((-3.25, 7.5, 0.5))


def test_round_trip_maps_in_between_values_like_map_saver(tmp_path):
    data = np.array([[0, 30, 64, 65, 99, -1]], dtype=np.int8)
    _, yaml_path = map_io.save_map(tmp_path / "rt", make_map(data))
    assert map_io.load_map(yaml_path).data.tolist() == [[0, -1, -1, 100, 100, -1]]


def test_existing_map_survives_a_failed_save(tmp_path, monkeypatch):
    old = make_map([[100, 0]])
    pgm_path, yaml_path = map_io.save_map(tmp_path / "map", old)
    before = (pgm_path.read_bytes(), yaml_path.read_bytes())

    calls = []
    real_fsync = os.fsync

    def failing_fsync(fd):
        calls.append(fd)
        if len(calls) == 2:  # the second file (the YAML) fails, e.g. disk full
            raise OSError(28, "No space left on device")
        real_fsync(fd)

    monkeypatch.setattr(os, "fsync", failing_fsync)
    with pytest.raises(OSError, match="No space"):
        map_io.save_map(tmp_path / "map", make_map([[0, 0, 0]], resolution=0.1))
    monkeypatch.undo()
    assert (pgm_path.read_bytes(), yaml_path.read_bytes()) == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["map.pgm", "map.yaml"]


def test_save_into_a_missing_directory_fails_cleanly(tmp_path):
    with pytest.raises(FileNotFoundError, match="nowhere"):
        map_io.save_map(tmp_path / "nowhere" / "map", make_map([[0]]))
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    "occupied, free, message",
    [(0, 0, "between 1 and 100"), (101, 0, "between 1 and 100"), (50, -1, "between 0 and 100")],
)
def test_bad_save_thresholds(tmp_path, occupied, free, message):
    with pytest.raises(ValueError, match=message):
        map_io.save_map(tmp_path / "m", make_map([[0]]), occupied=occupied, free=free)


def test_free_must_be_below_occupied(tmp_path):
    with pytest.raises(ValueError, match="smaller"):
        map_io.save_map(tmp_path / "m", make_map([[0]]), occupied=40, free=40)


def test_refuses_empty_or_nonsense_maps(tmp_path):
    with pytest.raises(map_io.MapError, match="empty"):
        map_io.save_map(tmp_path / "m", make_map(np.zeros((0, 4))))
    with pytest.raises(map_io.MapError, match="resolution"):
        map_io.save_map(tmp_path / "m", make_map([[0]], resolution=float("nan")))
    with pytest.raises(map_io.MapError, match="origin"):
        map_io.save_map(tmp_path / "m", make_map([[0]], origin=(0.0, float("inf"), 0.0)))
    assert list(tmp_path.iterdir()) == []


def test_from_flat_checks_sizes():
    omap = map_io.OccupancyMap.from_flat([0, 100, -1, 0, 0, 0], 3, 2, 0.05, (1, 2, 0))
    assert omap.data.tolist() == [[0, 100, -1], [0, 0, 0]]
    with pytest.raises(map_io.MapError, match="5 cells"):
        map_io.OccupancyMap.from_flat([0] * 5, 3, 2, 0.05, (0, 0, 0))
    with pytest.raises(map_io.MapError, match="empty"):
        map_io.OccupancyMap.from_flat([], 0, 0, 0.05, (0, 0, 0))


def test_base_name_accepts_file_suffixes():
    assert map_io.map_base_name("office") == "office"
    assert map_io.map_base_name("dir/office.pgm") == "dir/office"
    assert map_io.map_base_name("office.yaml") == "office"


def test_unwritable_folder_names_the_map_file(tmp_path, monkeypatch):
    import tempfile

    def denied(*args, **kwargs):
        raise PermissionError(13, "Permission denied", str(tmp_path / ".map.pgm.x.tmp"))

    monkeypatch.setattr(tempfile, "mkstemp", denied)
    with pytest.raises(PermissionError, match=r"cannot write .*map\.pgm: Permission denied"):
        map_io.save_map(tmp_path / "map", make_map([[0]]))
    assert list(tmp_path.iterdir()) == []
