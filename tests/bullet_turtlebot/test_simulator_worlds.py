"""Worlds: shipped worlds, any map_server map (willow), clear errors for bad world files,
and the ground-truth map export. Real roscore and simulator node."""

import math
from pathlib import Path

import pytest
from bullet_turtlebot import willow_plan
from map_server import map_io
from simkit import last_pose, ranges, start_simulator, write_pgm, write_world

WILLOW = Path(__file__).resolve().parents[2].parent / "shared" / "data" / "willow-full.pgm"
WORLDS = Path(__file__).resolve().parents[2] / "catkin_ws" / "src" / "bullet_turtlebot" / "worlds"


def run_simulator(ros, world, *extra):
    return ros.run(
        ["rosrun", "bullet_turtlebot", "simulator", f"_world:={world}", *extra],
        check=False,
        timeout=60,
    )


@pytest.mark.parametrize("world", ["playground", "maze", "office"])
def test_shipped_worlds_run_and_the_robot_sees_walls(ros, world):
    start_simulator(ros, world)
    scan = ros.echo("/scan", count=1)[0]["msg"]
    r = ranges(scan)
    assert len(r) == 640
    assert any(math.isfinite(v) for v in r)
    x, y, _, _ = last_pose(ros)
    assert math.isfinite(x) and math.isfinite(y)


@pytest.mark.parametrize("world", ["hospital", "warehouse", "ring", "lab"])
def test_generated_family_worlds_start_where_the_file_says_and_see_walls(ros, world):
    """The procedural families' shipped worlds (make_worlds.py --family F --seed 1)."""
    spec = (WORLDS / f"{world}.yaml").read_text()
    start = [float(v) for v in spec.split("\nstart: [")[1].split("]")[0].split(",")]
    start_simulator(ros, world)
    x, y, yaw, _ = last_pose(ros)
    assert abs(x - start[0]) < 1e-3 and abs(y - start[1]) < 1e-3
    assert abs(math.remainder(yaw - start[2], math.tau)) < 1e-3
    r = ranges(ros.echo("/scan", count=1)[0]["msg"])
    assert len(r) == 640
    walls = [v for v in r if math.isfinite(v)]
    assert len(walls) > 320 and min(walls) > 0.45  # walls in view, none too close


def bad_world_cases(tmp_path):
    write_pgm(tmp_path / "ok.pgm", [[254] * 10] * 10)
    (tmp_path / "bad.pgm").write_bytes(b"P5\n10 10\n255\n" + b"\x00" * 7)
    return {
        "missing": (tmp_path / "nope.yaml", "cannot open"),
        "syntax": (
            write_world(tmp_path, "syntax", extra="image: [unclosed\n"),
            "YAML syntax error at line",
        ),
        "no resolution": (
            write_world(tmp_path, "nores", extra="image: ok.pgm\norigin: [0, 0, 0]\n"),
            "missing key 'resolution'",
        ),
        "missing image": (
            write_world(
                tmp_path, "noimg", extra="image: gone.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n"
            ),
            "gone.pgm': cannot open",
        ),
        "truncated image": (
            write_world(
                tmp_path, "trunc", extra="image: bad.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n"
            ),
            "truncated pixel data",
        ),
        "start in a wall": (
            write_world(tmp_path, "inwall", boxes=[(0, 0, 0, 2, 2, 1)], start=(0, 0, 0)),
            "inside an obstacle",
        ),
    }


def test_bad_world_files_give_a_clear_error_and_nonzero_exit(ros, tmp_path):
    for case, (path, problem) in bad_world_cases(tmp_path).items():
        done = run_simulator(ros, path)
        output = done.stdout + done.stderr
        assert done.returncode != 0, case
        assert str(path) in output, (case, output)
        assert problem in output, (case, output)


def test_bad_world_through_roslaunch(ros, tmp_path):
    done = ros.run(
        ["roslaunch", "bullet_turtlebot", "simulator.launch", f"world:={tmp_path}/none.yaml"],
        check=False,
        timeout=60,
    )
    output = done.stdout + done.stderr
    assert f"world file '{tmp_path}/none.yaml': cannot open" in output
    assert "process has died" in output or "exit code 2" in output


def willow_world(tmp_path):
    """A YAML of our own for the Willow Garage plan, starting in a free spot near its middle."""
    data = WILLOW.read_bytes()
    fields = data.split(maxsplit=4)  # b"P5", b"#..." comment or width...
    lines = [line for line in data.split(b"\n")[:4] if not line.startswith(b"#")]
    width, height = map(int, lines[1].split())
    pixels = data[len(data) - width * height :]
    resolution = willow_plan.RESOLUTION
    clear = 6  # cells (0.6 m) of free space around the start

    def free(c, r):
        return all(
            pixels[(r + dr) * width + c + dc] > 250
            for dr in range(-clear, clear + 1)
            for dc in range(-clear, clear + 1)
        )

    cells = sorted(
        ((c, r) for r in range(clear, height - clear, 5) for c in range(clear, width - clear, 5)),
        key=lambda cr: (cr[0] - width / 2) ** 2 + (cr[1] - height / 2) ** 2,
    )
    col, row = next(cr for cr in cells if free(*cr))
    assert fields[0] == b"P5"
    x, y = (col + 0.5) * resolution, (height - row - 0.5) * resolution
    path = willow_plan.write_world(tmp_path / "willow.yaml", WILLOW, (x, y, 0.0))
    return path, x, y


@pytest.mark.skipif(not WILLOW.exists(), reason="shared willow-full.pgm not present")
def test_willow_map_with_a_yaml_of_our_own(ros, tmp_path):
    world, x, y = willow_world(tmp_path)
    start_simulator(ros, world)
    r = ranges(ros.echo("/scan", count=1)[0]["msg"])
    assert len(r) == 640
    tx, ty, _, _ = last_pose(ros)
    assert abs(tx - x) < 1e-6 and abs(ty - y) < 1e-6
    done = ros.run(
        ["rosrun", "bullet_turtlebot", "world_to_map", str(world), "-f", "willow_truth"]
        + ["--resolution", "0.1"]
    )
    assert "willow_truth.yaml" in done.stdout
    assert (tmp_path / "willow_truth.pgm").exists()


def read_pgm(path):
    data = Path(path).read_bytes()
    header = [line for line in data.split(b"\n")[:4] if not line.startswith(b"#")]
    width, height = map(int, header[1].split())
    return width, height, data[len(data) - width * height :]


def test_world_to_map_writes_a_map_server_map(ros, tmp_path):
    done = ros.run(
        [
            "rosrun",
            "bullet_turtlebot",
            "world_to_map",
            "maze",
            "-f",
            "truth",
            "--resolution",
            "0.05",
        ]
    )
    assert "truth.yaml" in done.stdout
    yaml = (tmp_path / "truth.yaml").read_text()
    # map_saver's YAML to the byte (rosbook_env's C++ writer and map_server's Python one),
    # and map_server's loader reads the pair back.
    truth = map_io.load_map(tmp_path / "truth.yaml")
    assert yaml == map_io.map_yaml_text("truth.pgm", truth.resolution, truth.origin)
    assert yaml.startswith("image: truth.pgm\nresolution: 0.050000\norigin: [")
    origin = list(truth.origin)
    width, height, pixels = read_pgm(tmp_path / "truth.pgm")
    # The maze is 10.5 m square with a 0.5 m margin each side.
    assert abs(width * 0.05 - 11.5) < 0.1 and abs(height * 0.05 - 11.5) < 0.1
    assert abs(origin[0] + 0.5) < 0.06 and abs(origin[1] + 0.5) < 0.06
    assert set(pixels) == {0, 254}
    occupied = pixels.count(0) / len(pixels)
    assert 0.05 < occupied < 0.4
    # The start cell (0.75, 0.75) is free; the outer wall at x = 0.05 is occupied.
    col = int((0.75 - origin[0]) / 0.05)
    row = height - 1 - int((0.75 - origin[1]) / 0.05)
    assert pixels[row * width + col] == 254
    col = int((0.05 - origin[0]) / 0.05)
    assert pixels[row * width + col] == 0
    bad = ros.run(["rosrun", "bullet_turtlebot", "world_to_map", "no_such_world"], check=False)
    assert bad.returncode != 0 and "no_such_world.yaml': cannot open" in bad.stderr


def test_world_without_start_and_origin_in_a_wall_starts_at_nearest_free_spot(ros, tmp_path):
    world = write_world(tmp_path, "nostart", boxes=[(0, 0, 0, 2, 2, 1)])
    sim = start_simulator(ros, world)
    x, y, _, _ = last_pose(ros)
    assert 1.18 < math.hypot(x, y) < 1.5
    assert "nearest free position" in ros.output(sim)
