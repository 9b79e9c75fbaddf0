"""End to end: the explorer maps the simulator's office world, SLAM in the loop, faster
than real time. Figures (coverage over sim time, contact, real-time factor) are printed."""

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from explore_launch import slam_node_available, start_exploration  # noqa: E402
from roskit import read_jsonl  # noqa: E402

# Sim speed 8; explore_sim.launch has the simulator wait for the explorer if it lags
# (wait_for_commands), so coverage per sim second does not depend on the machine's load.
SPEED = float(os.environ.get("EXPLORER_SIM_SPEED", "8"))
# Measured with gmapping_lite (seed 1, speed 8, machine loaded): 52% at 200 s, 70% at 300 s,
# 80% at 400 s, 88% at 600 s. 300 s and 60% tell an exploring robot from a stuck one (what
# the start room and the opening spin show is about 21%); the bench measures full coverage.
SIM_SECONDS = float(os.environ.get("EXPLORER_SIM_SECONDS", "300"))
COVERAGE_AT_END = 0.60


def records(path):
    return read_jsonl(path)


def run_exploration(ros, tmp_path, world="office", use_slam=True):
    """Start everything paused, then run SIM_SECONDS of sim time; return the records."""
    if (
        shutil.which("rospack") is None
        or subprocess.run(["rospack", "find", "bullet_turtlebot"], capture_output=True).returncode
    ):
        pytest.skip("bullet_turtlebot is not in this workspace")
    out = start_exploration(ros, tmp_path, world, SPEED, use_slam, tmp_path / "map.pgm")

    def finished():
        got = records(out)
        for proc in ros.procs:
            assert proc.poll() is None, f"{proc.label} died:\n" + ros.output(proc)[-3000:]
        return got and (got[-1]["sim"] - got[0]["sim"] >= SIM_SECONDS or got[-1]["done"])

    ros.wait_for(
        finished, SIM_SECONDS / SPEED * 6 + 120, f"{SIM_SECONDS:g} s of sim time", interval=1.0
    )
    return records(out)


def report(got, label):
    t0, w0 = got[0]["sim"], got[0]["wall"]
    last = got[-1]
    elapsed = last["sim"] - t0
    lines = [f"{label}: coverage over sim time (speed {SPEED})"]
    for r in got:
        if round(r["sim"] - t0) % 50 == 0:
            lines.append(f"  {r['sim'] - t0:5.0f} s  {r['coverage']:6.1%}")
    lines.append(
        f"  final {last['coverage']:.1%} at {elapsed:.0f} s sim, contact "
        f"{last['contact'] / max(elapsed, 1e-9):.1%}, done {last['done']}, real-time factor "
        f"{elapsed / (last['wall'] - w0):.1f}"
    )
    print("\n".join(lines))
    return last, elapsed


@pytest.mark.slow
def test_explorer_maps_the_office_with_slam(ros, tmp_path):
    if not slam_node_available():
        pytest.skip("gmapping_lite's slam_gmapping is not built in this workspace")
    got = run_exploration(ros, tmp_path, use_slam=True)
    last, elapsed = report(got, "office, gmapping_lite")
    assert last["coverage"] >= COVERAGE_AT_END
    assert last["contact"] / elapsed < 0.05


@pytest.mark.slow
def test_explorer_maps_the_office_with_perfect_odometry(ros, tmp_path):
    """The same without SLAM (a stand-in mapper on perfect odometry), for workspaces that
    do not build gmapping_lite."""
    if slam_node_available():
        pytest.skip("gmapping_lite is built: the SLAM test covers this")
    got = run_exploration(ros, tmp_path, use_slam=False)
    last, elapsed = report(got, "office, perfect odometry")
    assert last["coverage"] >= COVERAGE_AT_END
    assert last["contact"] / elapsed < 0.05
