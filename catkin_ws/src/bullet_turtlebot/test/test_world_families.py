"""The procedural world families: same seed, same bytes; every world explorable by the
Turtlebot (start in the open, all free space reachable, doors wide and unblocked); sizes in
range; each family's character (hospital doors, warehouse openness, the ring's loop, the
lab's see-through gaps). Pure Python: no ROS master."""

import hashlib
import os
import subprocess
import sys
import tempfile
from collections import Counter
from functools import cache
from pathlib import Path

import numpy as np
import pytest
from bullet_turtlebot import world_families
from bullet_turtlebot.world_check import clearance, holes, load_grid, passable, problems, reachable
from bullet_turtlebot.world_families import generate, size_range
from bullet_turtlebot.world_file import Plan, World, write_world

PACKAGE = Path(__file__).resolve().parent.parent
SCRIPT = PACKAGE / "scripts" / "make_worlds.py"
FAMILIES = list(world_families.FAMILIES)
SEEDS = range(1, 6)
CASES = [(family, seed) for family in FAMILIES for seed in SEEDS]
MIN_DOOR = 0.9  # m
WORK = tempfile.TemporaryDirectory(prefix="world_families_")  # removed at exit


@cache
def built(family, seed):
    """(World, Grid) of a family and seed, written to and read back from files."""
    world = generate(family, seed)
    return world, load_grid(write_world(WORK.name, world))


def digest(world, folder):
    folder.mkdir()
    path = write_world(folder, world)
    return hashlib.sha256(path.read_bytes() + path.with_suffix(".pgm").read_bytes()).hexdigest()


def free_run(line, index):
    """Length of the run of free cells through line[index]."""
    if line[index]:
        return 0
    lo = hi = index
    while lo > 0 and not line[lo - 1]:
        lo -= 1
    while hi < len(line) - 1 and not line[hi + 1]:
        hi += 1
    return hi - lo + 1


def opening_width(grid, opening):
    """Clear width measured on the grid along the wall, through the opening's centre; the
    wall is two cells thick, so both rows (or columns) through it are measured."""
    widths = []
    for offset in (-grid.resolution / 2, grid.resolution / 2):
        if opening.along_x:
            i, j = grid.cell(opening.x, opening.y + offset)
            widths.append(free_run(grid.occupied[i, :], j))
        else:
            i, j = grid.cell(opening.x + offset, opening.y)
            widths.append(free_run(grid.occupied[:, j], i))
    return min(widths) * grid.resolution


@pytest.mark.parametrize("family", FAMILIES)
def test_the_same_family_and_seed_give_the_same_bytes(family, tmp_path):
    first = digest(generate(family, 7), tmp_path / "a")
    assert digest(generate(family, 7), tmp_path / "b") == first
    assert digest(generate(family, 8), tmp_path / "c") != first


def test_bytes_do_not_depend_on_the_process(tmp_path):
    """A fresh interpreter with another hash seed writes the same files."""
    code = (
        "import sys; from bullet_turtlebot.world_families import generate, FAMILIES;"
        "from bullet_turtlebot.world_file import write_world;"
        "[write_world(sys.argv[1], generate(f, 3)) for f in FAMILIES]"
    )
    env = dict(os.environ, PYTHONHASHSEED="12345", PYTHONPATH=str(PACKAGE / "src"))
    subprocess.run([sys.executable, "-c", code, str(tmp_path)], env=env, check=True)
    for family in FAMILIES:
        (tmp_path / "here").mkdir(exist_ok=True)
        write_world(tmp_path / "here", generate(family, 3))
        for suffix in (".yaml", ".pgm"):
            name = f"{family}_3{suffix}"
            assert (tmp_path / name).read_bytes() == (tmp_path / "here" / name).read_bytes()


@pytest.mark.parametrize("family", world_families.SHIPPED)
def test_shipped_family_worlds_are_what_the_generator_writes(family, tmp_path):
    write_world(tmp_path, generate(family, 1, name=family))
    for suffix in (".yaml", ".pgm"):
        shipped = PACKAGE / "worlds" / f"{family}{suffix}"
        assert shipped.read_bytes() == (tmp_path / f"{family}{suffix}").read_bytes(), (
            "worlds/ is stale: "
            "rosrun bullet_turtlebot make_worlds.py catkin_ws/src/bullet_turtlebot/worlds"
        )


def test_the_yaml_header_records_family_and_seed(tmp_path):
    text = write_world(tmp_path, generate("ring", 4)).read_text()
    assert text.startswith("# ring_4: family ring, seed 4; ")
    assert "make_worlds.py --family ring --seed 4" in text.splitlines()[1]


@pytest.mark.parametrize("family,seed", CASES)
def test_every_free_place_is_reachable_from_the_start(family, seed):
    _, grid = built(family, seed)
    unreachable = passable(grid) & ~reachable(grid)
    assert not unreachable.any(), problems(grid)
    assert reachable(grid).sum() * grid.resolution**2 > 50  # m2: the flood fill went far


@pytest.mark.parametrize("family,seed", CASES)
def test_the_start_has_half_a_metre_of_free_space(family, seed):
    _, grid = built(family, seed)
    # Clearance is measured from cell centres: allow half a cell.
    assert clearance(grid)[grid.cell(*grid.start[:2])] >= 0.5 - grid.resolution / 2


@pytest.mark.parametrize("family,seed", CASES)
def test_sizes_are_within_the_family_range(family, seed):
    world, grid = built(family, seed)
    width, height = world.size
    (wlo, whi), (hlo, hhi) = size_range(family)
    assert wlo <= width <= whi and hlo <= height <= hhi
    assert max(width, height) <= world_families.MAX_SIZE
    assert grid.occupied.shape == (round(height / 0.05), round(width / 0.05))


@pytest.mark.parametrize("family,seed", CASES)
def test_doors_are_wide_enough_and_not_blocked(family, seed):
    world, grid = built(family, seed)
    if family in ("office", "hospital", "lab"):
        assert world.doors
    xs, ys = grid.centres()
    for door in world.doors:
        measured = opening_width(grid, door)
        assert measured >= max(MIN_DOOR, door.width - grid.resolution / 2), door
        # Nothing stands within 0.6 m of the doorway on either side.
        half_along, half_across = door.width / 2, 0.6
        if not door.along_x:
            half_along, half_across = half_across, half_along
        near = (np.abs(xs - door.x) < half_along) & (np.abs(ys - door.y) < half_across)
        assert not (grid.occupied & near).any(), door


def test_door_widths_vary_in_offices_and_repeat_in_hospitals():
    office = Counter(d.width for seed in SEEDS for d in built("office", seed)[0].doors)
    assert len(office) >= 4 and min(office) >= MIN_DOOR and max(office) <= 1.4
    for seed in SEEDS:
        doors = Counter(d.width for d in built("hospital", seed)[0].doors)
        assert doors.most_common(1)[0][1] >= 0.75 * sum(doors.values())  # many similar doors


@pytest.mark.parametrize("seed", SEEDS)
def test_hospital_corridor_has_rooms_on_both_sides(seed):
    world, _ = built("hospital", seed)
    corridor = world.size[0]
    assert 30 <= corridor <= 40
    along = [d for d in world.doors if d.along_x]
    south = {round(d.y, 3) for d in along if d.y < world.start[1]}
    north = {round(d.y, 3) for d in along if d.y > world.start[1]}
    assert len(south) == 1 and len(north) == 1  # one corridor wall on each side
    assert sum(d.y < world.start[1] for d in along) >= 7
    assert sum(d.y > world.start[1] for d in along) >= 7


@pytest.mark.parametrize("seed", SEEDS)
def test_warehouse_is_a_big_open_hall(seed):
    world, grid = built("warehouse", seed)
    width, height = world.size
    assert width >= 25 and height >= 20
    free = ~grid.occupied
    assert (clearance(grid)[free] > 3.0).mean() >= 0.15
    racks = sorted(
        (pose[1] - size[1] / 2, pose[1] + size[1] / 2, pose[0])
        for pose, size, _ in world.boxes
        if size[0] >= 4.0
    )
    assert len(racks) >= 4
    by_x = {}
    for low, high, x in racks:
        by_x.setdefault(x, []).append((low, high))
    for rows in by_x.values():  # aisles between neighbouring rows of a block
        assert all(b[0] - a[1] >= 1.5 for a, b in zip(rows, rows[1:], strict=False))


@pytest.mark.parametrize("seed", SEEDS)
def test_ring_corridor_loops_round_the_block(seed):
    _, grid = built("ring", seed)
    region = reachable(grid)
    found = holes(region)
    assert found, "the reachable space is simply connected: no loop"
    cells, (rows, cols) = found[0]
    assert cells * grid.resolution**2 >= 20  # m2: the central block, not a bin
    # The loop's centre line lies between the block's outline and the corridor's outer edge.
    inner = 2 * (rows.stop - rows.start + cols.stop - cols.start)
    free_rows, free_cols = np.nonzero(region)
    outer = 2 * (np.ptp(free_rows) + np.ptp(free_cols))
    assert (inner + outer) / 2 * grid.resolution >= 40


@pytest.mark.parametrize("seed", SEEDS)
def test_lab_gaps_let_the_laser_through_but_not_the_robot(seed):
    world, grid = built("lab", seed)
    assert len(world.gaps) >= 2
    free_to_drive = passable(grid)
    for gap in world.gaps:
        assert 0.2 <= gap.width <= 0.4
        assert opening_width(grid, gap) >= gap.width - grid.resolution / 2
        i, j = grid.cell(gap.x, gap.y)
        assert not free_to_drive[i - 1 : i + 2, j - 1 : j + 2].any(), gap
    assert len(world.boxes) + len(world.cylinders) >= 15  # cluttered


def test_the_check_finds_a_sealed_room_and_a_cramped_start(tmp_path):
    plan = Plan(6.0, 4.0)
    plan.outline()
    plan.vwall(3.0, 0.0, 4.0)  # no door: the east half is sealed off
    world = World("sealed", plan, origin=(0.0, 0.0, 0.0), start=(0.3, 2.0, 0.0))
    found = problems(load_grid(write_world(tmp_path, world)))
    assert any("unreachable" in p for p in found) and any("start" in p for p in found)


def test_script_writes_a_named_family_world(tmp_path):
    # The package and rosbook_env (world_check's YAML loader), without a catkin build.
    sources = (PACKAGE / "src", PACKAGE.parent / "rosbook_env" / "src")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(map(str, sources)))
    done = subprocess.run(
        [
            sys.executable,
            str(SCRIPT),
            "--family",
            "lab",
            "--seed",
            "2",
            "--name",
            "bench",
            tmp_path,
        ],
        env=env,
        capture_output=True,
        text=True,
        check=True,
    )
    assert "bench.yaml" in done.stdout
    assert (tmp_path / "bench.pgm").exists()
    header = (tmp_path / "bench.yaml").read_text().splitlines()[0]
    assert header.startswith("# bench: family lab, seed 2; ")
