import math

import numpy as np
from explorer.exploration import FOLLOW, LOOK, RECOVER, SPIN, WAIT, Explorer, ExplorerParams
from explorer.map_planner import Plan


def plan(goal=(2.0, 0.0), looks=(0.0,), kept=False):
    path = np.array([[0.0, 0.0], [1.0, 0.0], list(goal)])
    return Plan(goal, path, list(looks), 2.0, 1.0, 5.0, 3, kept, (goal[0] + 1.0, goal[1]))


def spun(explorer):
    """Run the initial look-around; returns the time after it."""
    t, yaw = 0.0, 0.0
    while explorer.state == SPIN:
        _, w = explorer.control(t, 0.0, 0.0, yaw)
        yaw += w * 0.1
        t += 0.1
    return t


def test_starts_by_turning_round_then_asks_for_a_plan():
    explorer = Explorer()
    v, w = explorer.control(0.0, 0.0, 0.0, 0.0)
    assert explorer.state == SPIN and v == 0 and w > 0
    assert not explorer.wants_plan(0.0, 1.0)
    t = spun(explorer)
    assert 2 * math.pi / 0.8 <= t <= 2 * math.pi / 0.8 + 0.5
    assert explorer.state == WAIT and explorer.wants_plan(t, 1.0)
    assert not explorer.wants_plan(t, None)  # no map yet


def test_follows_a_plan_reaches_the_goal_and_looks():
    explorer = Explorer()
    t = spun(explorer)
    explorer.accept_plan(plan(looks=(1.0,)), t, map_stamp=t)
    assert explorer.state == FOLLOW and explorer.current_goal == (2.0, 0.0)
    assert any("goal (2.00, 0.00)" in e for e in explorer.events)
    v, w = explorer.control(t, 0.0, 0.0, 0.0)
    assert v > 0
    explorer.control(t + 5, 1.9, 0.0, 0.0)  # within the goal tolerance
    assert explorer.state == LOOK and explorer.goals_reached == 1
    yaw = 0.0
    for k in range(100):
        _, w = explorer.control(t + 5 + k * 0.1, 1.9, 0.0, yaw)
        yaw += w * 0.1
        if explorer.state != LOOK:
            break
    assert explorer.state == WAIT and explorer.plan_requested
    assert explorer.pending_views(map_stamp=t)  # looked after that map was made
    assert explorer.pending_views(map_stamp=t + 100) == []


def test_done_after_plans_without_frontiers_and_resumes():
    explorer = Explorer()
    t = spun(explorer)
    explorer.accept_plan(None, t, map_stamp=1.0)
    assert explorer.state == WAIT
    explorer.accept_plan(None, t + 1, map_stamp=2.0)
    assert explorer.done
    assert explorer.control(t + 2, 0.0, 0.0, 0.0) == (0.0, 0.0)
    assert not explorer.wants_plan(t + 2, 2.0)  # same map
    assert explorer.wants_plan(t + 10, 3.0)  # a new map, later
    explorer.accept_plan(plan(), t + 10, map_stamp=3.0)
    assert explorer.state == FOLLOW and not explorer.done


def test_bumper_backs_off_and_blacklists_the_goal():
    explorer = Explorer()
    t = spun(explorer)
    explorer.accept_plan(plan(), t, map_stamp=t)
    explorer.bumped(t + 1)
    assert explorer.state == RECOVER
    assert explorer.excluded_points(t + 1) == [(2.0, 0.0)]
    v, _ = explorer.control(t + 1.1, 0.5, 0.0, 0.0)
    assert v < 0  # backing up
    later = t + 1 + explorer.recovery_params.backup_time + explorer.recovery_params.turn_time
    explorer.control(later + 0.1, 0.4, 0.0, 1.0)
    assert explorer.state == WAIT and explorer.plan_requested


def test_stuck_robot_recovers():
    explorer = Explorer()
    t = spun(explorer)
    explorer.accept_plan(plan(goal=(5.0, 0.0)), t, map_stamp=t)
    states = set()
    for k in range(100):  # commanded forward, never moving
        explorer.control(t + k * 0.1, 0.0, 0.0, 0.0, clearance=math.inf)
        states.add(explorer.state)
    assert RECOVER in states
    assert any("stuck" in e for e in explorer.events)


def test_a_frontier_looked_at_twice_is_ignored():
    explorer = Explorer()
    t = spun(explorer)
    for _ in range(2):
        explorer.accept_plan(plan(), t, map_stamp=t)
        explorer.control(t, 2.0, 0.0, 0.0)  # arrive at once
        t += 1
    assert explorer.excluded_frontiers(t) == [(3.0, 0.0)]
    assert not explorer.done


def test_initial_spin_can_be_skipped():
    explorer = Explorer(ExplorerParams(initial_spin=0.0))
    assert explorer.state == WAIT and explorer.wants_plan(0.0, 1.0)
