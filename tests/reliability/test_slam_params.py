"""Reliability matrix for slam_gmapping's parameters (gmapping_lite): a value the filter
cannot work with ends slam_offline and the slam_gmapping node at start-up with exit code 2
and one line naming the parameter, its value and what is allowed, before any scan is read.
Each row: the parameter and its bad value. slam_offline rows need no roscore; the node rows
share one (each row clears the node's private parameters first)."""

import subprocess

import pytest
from roskit import ros_environment

CASES = {
    "particles 0": ("particles", "0"),
    "particles a million": ("particles", "1000000"),
    "delta 0": ("delta", "0"),
    "delta negative": ("delta", "-0.05"),
    "delta too fine for the map": ("delta", "0.001"),
    "xmin above xmax": ("xmin", "200"),
    "resampleThreshold 0": ("resampleThreshold", "0"),
    "occ_thresh 1": ("occ_thresh", "1"),
    "linearUpdate negative": ("linearUpdate", "-1"),
    "astep 0": ("astep", "0"),
    "iterations 1000": ("iterations", "1000"),
    "maxRange 0": ("maxRange", "0"),
    "srr negative": ("srr", "-0.1"),
    "particles 2.5": ("particles", "2.5"),  # was cut to 2 particles
    "seed negative": ("seed", "-1"),  # was undefined as an unsigned seed
    "loop_closure 5": ("loop_closure", "5"),
}
NODE_CASES = ["particles 0", "delta 0", "xmin above xmax", "maxRange 0", "particles 2.5"]


@pytest.mark.parametrize("case", sorted(CASES))
def test_slam_offline_refuses_a_bad_parameter_before_reading_the_bag(tmp_path, case):
    name, value = CASES[case]
    cmd = ["rosrun", "gmapping_lite", "slam_offline", str(tmp_path / "never-read.bag")]
    done = subprocess.run(
        [*cmd, "--param", f"{name}={value}"],
        capture_output=True,
        text=True,
        timeout=60,
        env=ros_environment(11311),
    )
    assert done.returncode == 2, done.stdout + done.stderr
    first = done.stderr.splitlines()[0]
    assert first.startswith(f"slam_offline: {name} is ") and "it must be" in first, first


@pytest.mark.parametrize("case", NODE_CASES)
def test_slam_gmapping_refuses_a_bad_parameter_at_start_up(shared_ros, case):
    name, value = CASES[case]
    shared_ros.master().deleteParam("/test_slam_params", "/slam_gmapping")
    cmd = ["rosrun", "gmapping_lite", "slam_gmapping", f"_{name}:={value}"]
    done = shared_ros.run(cmd, check=False, timeout=120)
    assert done.returncode == 2, done.stdout + done.stderr
    line = next(x for x in done.stderr.splitlines() if x.startswith("slam_gmapping: ~"))
    assert f"~{name} is " in line and "it must be" in line and "_NAME:=VALUE" in line, line


def test_slam_gmapping_takes_loop_closure_true(shared_ros):
    """~loop_closure is a switch: `_loop_closure:=true` was refused as "'' must be a number"."""
    shared_ros.master().deleteParam("/test_slam_params", "/slam_gmapping")
    proc = shared_ros.start(["rosrun", "gmapping_lite", "slam_gmapping", "_loop_closure:=true"])
    shared_ros.wait_for_service("/dynamic_map", timeout=60)
    shared_ros.stop(proc)
    out = shared_ros.output(proc)
    assert "loop_closure" not in out, out
