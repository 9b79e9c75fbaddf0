"""world_start: the start pose the simulator uses, resolved from a name or a path as the
simulator resolves it; a missing `start` is the origin; bad files get a clear error."""

import re
import subprocess
from pathlib import Path

import pytest
from bullet_turtlebot.world_start import start_pose, world_path

PACKAGE = Path(__file__).resolve().parent.parent
WORLDS = PACKAGE / "worlds"


def test_a_shipped_world_by_name_and_by_path():
    assert start_pose("office", WORLDS) == (-8.5, 0.0, 0.0)
    assert start_pose(str(WORLDS / "maze.yaml"), "/nowhere") == (0.75, 0.75, 0.0)
    assert world_path("lab.yaml", WORLDS) == Path("lab.yaml")  # as the simulator: a path


def test_a_world_without_start_starts_at_the_origin(tmp_path):
    world = tmp_path / "w.yaml"
    world.write_text("image: w.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n")
    assert start_pose(str(world), WORLDS) == (0.0, 0.0, 0.0)


@pytest.mark.parametrize(
    "text, message",
    [
        ("start: [1]\n", "'start' must be [x, y] or [x, y, yaw]"),
        ("start: [1e300, 0, 0]\n", "metres within 1e6 of the origin"),
        ("start: [true, 0, 0]\n", "'start' must be"),
        ("start: [a\n", "not YAML"),
        pytest.param("start: " + "[" * 1000 + "]" * 1000 + "\n", "nested too deeply", id="nested"),
    ],
)
def test_bad_world_files_are_named(tmp_path, text, message):
    world = tmp_path / "bad.yaml"
    world.write_text(text)
    with pytest.raises(ValueError, match=re.escape(message)):
        start_pose(str(world), WORLDS)
    with pytest.raises(ValueError, match="cannot read world file"):
        start_pose("no_such_world", WORLDS)


def test_the_script_prints_one_component():
    script = PACKAGE / "scripts" / "world_start.py"
    # The two packages' own modules and nothing else of the workspace's environment.
    sources = [PACKAGE / "src", PACKAGE.parent / "rosbook_env" / "src"]
    env = {"PYTHONPATH": ":".join(map(str, sources)), "PATH": "/usr/bin:/bin"}
    done = subprocess.run(
        [str(script), "office", "x", str(WORLDS)], capture_output=True, text=True, env=env
    )
    assert (done.returncode, done.stdout.strip()) == (0, "-8.5")
    done = subprocess.run([str(script), "nope", "yaw"], capture_output=True, text=True, env=env)
    assert done.returncode == 1 and "world_start.py: cannot read world file" in done.stderr


def test_the_start_forms_the_simulator_takes(tmp_path):
    world = tmp_path / "w.yaml"
    world.write_text("start: [1e1, -2]\n")  # [x, y], and 1e1 a number as in yaml-cpp
    assert start_pose(str(world), WORLDS) == (10.0, -2.0, 0.0)


def test_a_device_is_refused_not_read():
    with pytest.raises(ValueError, match="/dev/zero: not a regular file"):
        start_pose("/dev/zero", WORLDS)


def test_a_key_given_twice_is_refused_naming_the_file_and_the_key(tmp_path):
    world = tmp_path / "w.yaml"
    world.write_text("image: w.pgm\nstart: [1, 2, 0]\nresolution: 0.05\nstart: [3, 4, 0]\n")
    with pytest.raises(ValueError, match=r"w.yaml: .*key 'start' given twice \(lines 2 and 4\)"):
        start_pose(str(world), WORLDS)
