"""The explorer on procedural family worlds without ROS (kinematic_run: perfect pose, a
Kinect-like ray fan, a map published only after it integrated a scan, as gmapping does):
it maps nearly all the reachable free space and never declares itself done before that.

The ring is the case that made it stop early: a view from the corridor grazes along the
shadow a corner casts, so looking at that frontier from afar reveals nothing, and the
frontier used to be dropped; now it is approached closely, and set-aside frontiers are
retried before `done`."""

import sys
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from explorer.exploration import Explorer  # noqa: E402
from explorer.map_planner import MapPlanner  # noqa: E402
from kinematic_run import explore, family_world  # noqa: E402

# Measured: ring_1 91% at 300 s, 100% when done at 621 s (before the close approaches and
# retries: 38% at 300 s, stuck at 87% from 900 s on); office_1 99% at 600 s, 99.8% at
# 900 s; lab_4 98% at 300 s, 99.8% when done at 497 s.
CASES = [("ring", 1, 900), ("office", 1, 900), ("lab", 4, 600)]


@pytest.mark.slow
@pytest.mark.timeout(600)
@pytest.mark.parametrize("family,seed,seconds", CASES)
def test_explores_a_family_world_and_is_done_only_at_the_end(tmp_path, family, seed, seconds):
    world, start = family_world(family, seed, tmp_path)
    explorer = Explorer()
    done_at = []

    def on_step(now, explorer, mapper, reachable):
        if explorer.done and not done_at:
            done_at.append((now, float((mapper.known() & reachable).sum() / reachable.sum())))

    result = explore(world, start, seconds, explorer, MapPlanner(), on_step=on_step)
    print(f"{family}_{seed}: {result.coverage:.1%} at {result.sim_time:.0f} s, done {done_at}")
    assert result.coverage >= 0.97
    assert result.collisions * 0.1 / result.sim_time < 0.01  # bumper contact, share of time
    if done_at:
        assert done_at[0][1] >= 0.97  # done only once (nearly) everything is mapped
