"""The building-scale campus world (bench_simulator's 100 x 100 m row): its size, the same bytes
every time, family buildings that keep their walls, furniture and start.
Pure Python: no ROS master."""

import tempfile
from functools import cache
from pathlib import Path

import pytest
from bullet_turtlebot import world_families
from bullet_turtlebot.campus import STREET, campus
from bullet_turtlebot.world_file import RESOLUTION, write_world

WORK = tempfile.TemporaryDirectory(prefix="campus_")  # removed at exit


@cache
def written(size):
    world = campus(size)
    folder = Path(WORK.name) / f"{size:g}"
    folder.mkdir()
    return world, write_world(folder, world)


def test_a_100_m_campus_is_2000_cells_square_at_5_cm():
    world, path = written(100.0)
    assert world.size == (100.0, 100.0)
    assert (world.plan.cols, world.plan.rows) == (2000, 2000)
    assert f"resolution: {RESOLUTION}" in path.read_text()


def test_the_same_size_gives_the_same_bytes(tmp_path):
    _, path = written(100.0)
    again = write_world(tmp_path, campus(100.0))
    for suffix in (".yaml", ".pgm"):
        assert again.with_suffix(suffix).read_bytes() == path.with_suffix(suffix).read_bytes()


def test_it_holds_many_family_buildings_with_their_furniture():
    world, _ = written(100.0)
    first = world_families.generate(list(world_families.FAMILIES)[0], 1)
    assert world.comment.count("_") >= 15  # building names: family_seed
    assert len(world.boxes) > 10 * len(first.boxes)
    assert len(world.cylinders) > 0


def test_the_start_and_furniture_are_the_first_buildings_moved_with_it():
    """The family checks its start (room around it, everything reachable); here it only moves
    by the building's offset: its lower-left corner goes from -size/2 to a street from the
    campus's lower-left corner. (world_check.load_grid would take minutes on 4 Mpixels.)"""
    world, _ = written(100.0)
    first = world_families.generate(list(world_families.FAMILIES)[0], 1)
    dx = STREET + world.origin[0] - first.origin[0]
    dy = STREET + world.origin[1] - first.origin[1]
    assert world.start == pytest.approx((first.start[0] + dx, first.start[1] + dy, first.start[2]))
    for (pose, size, colour), (want_pose, want_size, want_colour) in zip(
        world.boxes[: len(first.boxes)], first.boxes, strict=True
    ):
        assert pose == pytest.approx((want_pose[0] + dx, want_pose[1] + dy, want_pose[2]))
        assert (size, colour) == (want_size, want_colour)


def test_the_first_building_is_pasted_cell_for_cell():
    world, _ = written(100.0)
    first = world_families.generate(list(world_families.FAMILIES)[0], 1)
    src = first.plan
    offset = round(STREET / RESOLUTION)
    for row in range(src.rows):
        dst_row = world.plan.rows - 1 - (offset + src.rows - 1 - row)
        start = dst_row * world.plan.cols + offset
        got = world.plan.pixels[start : start + src.cols]
        assert got == src.pixels[row * src.cols : (row + 1) * src.cols], f"row {row}"


def test_a_campus_too_small_for_a_building_is_refused():
    with pytest.raises(ValueError, match="too small"):
        campus(50.0)
