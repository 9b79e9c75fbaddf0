"""End to end on a procedural family world: the explorer and the simulator, with the
stand-in mapper on perfect odometry, on ring seed 5, a 47 m loop corridor whose corners
cast the grazing shadows that used to make the explorer give frontiers up. It keeps
exploring: `explorer/done` never turns true while much of the loop is unmapped.

The mapper is the stand-in, not SLAM, because coverage is scored with the map placed at
the start pose: SLAM's drift on a ring (issue 16) cost up to 16 points of it, so an explorer
that was right to stop failed the test. test_explore_sim covers the explorer with SLAM."""

import subprocess
import sys
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from explore_launch import start_exploration  # noqa: E402
from roskit import read_jsonl  # noqa: E402

FAMILY, SEED = "ring", 5
SIM_SECONDS = 300.0
SPEED = 5.0


@pytest.mark.slow
@pytest.mark.timeout(900)
def test_explorer_keeps_exploring_a_ring_world(ros, tmp_path):
    if subprocess.run(["rospack", "find", "bullet_turtlebot"], capture_output=True).returncode:
        pytest.skip("bullet_turtlebot is not in this workspace")
    make = ["rosrun", "bullet_turtlebot", "make_worlds.py", "--family", FAMILY]
    ros.run([*make, "--seed", str(SEED), str(tmp_path)], timeout=60)
    world = tmp_path / f"{FAMILY}_{SEED}.yaml"
    out = start_exploration(ros, tmp_path, world, SPEED, use_slam=False)

    def finished():
        got = read_jsonl(out)
        for proc in ros.procs:
            assert proc.poll() is None, f"{proc.label} died:\n" + ros.output(proc)[-3000:]
        return got and (got[-1]["sim"] - got[0]["sim"] >= SIM_SECONDS or got[-1]["done"])

    ros.wait_for(finished, SIM_SECONDS / SPEED * 6 + 120, f"{SIM_SECONDS:g} s of sim time")
    got = read_jsonl(out)
    t0 = got[0]["sim"]
    print(
        f"{FAMILY}_{SEED}: "
        + ", ".join(f"{r['sim'] - t0:.0f} s {r['coverage']:.0%}" for r in got[::5])
        + f"; last {got[-1]['coverage']:.1%} at {got[-1]['sim'] - t0:.0f} s, "
        f"done {got[-1]['done']}"
    )
    for record in got:
        # Done only once nearly all the loop is mapped.
        assert not record["done"] or record["coverage"] >= 0.85, record
    assert got[-1]["coverage"] >= 0.70
    elapsed = got[-1]["sim"] - t0
    assert got[-1]["contact"] / max(elapsed, 1e-9) < 0.05
