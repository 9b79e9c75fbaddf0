import math

import numpy as np
from move_base_lite.global_planner import PlanResult
from move_base_lite.navigator import ABORTED, SUCCEEDED, Navigator


def straight_plan(start, goal):
    xs = np.linspace(start[0], goal[0], 50)
    ys = np.linspace(start[1], goal[1], 50)
    return PlanResult(np.column_stack([xs, ys]))


def drive(nav, pose, plan, clearance=math.inf, seconds=60.0, dt=0.1):
    x, y, yaw = pose
    t = 0.0
    while t < seconds and nav.status == "active":
        cmd = nav.step(t, (x, y, yaw), clearance, plan)
        yaw += cmd.angular * dt
        x += cmd.linear * math.cos(yaw) * dt
        y += cmd.linear * math.sin(yaw) * dt
        t += dt
    return x, y, yaw, t


def test_reaches_the_goal_within_tolerance_and_faces_its_heading():
    nav = Navigator((2.0, 1.0, math.pi / 2))
    x, y, yaw, _ = drive(nav, (0.0, 0.0, 0.0), straight_plan)
    assert nav.status == SUCCEEDED
    assert math.hypot(x - 2.0, y - 1.0) <= nav.params.xy_goal_tolerance + 0.02
    assert abs(math.atan2(math.sin(yaw - math.pi / 2), math.cos(yaw - math.pi / 2))) <= 0.1


def test_an_invalid_goal_aborts_at_once_with_the_planners_reason():
    nav = Navigator((5.0, 0.0, 0.0))
    _, _, _, t = drive(nav, (0.0, 0.0, 0.0), lambda s, g: PlanResult(None, "goal in a wall", True))
    assert nav.status == ABORTED and "goal in a wall" in nav.text
    assert t < 0.5


def test_no_path_aborts_after_recoveries_rather_than_hanging():
    nav = Navigator((5.0, 0.0, 0.0))
    drive(nav, (0.0, 0.0, 0.0), lambda s, g: PlanResult(None, "no path"), seconds=120)
    assert nav.status == ABORTED and "no path" in nav.text


def test_a_blocked_robot_recovers_then_gives_up():
    nav = Navigator((5.0, 0.0, 0.0))
    drive(nav, (0.0, 0.0, 0.0), straight_plan, clearance=0.2, seconds=300)
    assert nav.status == ABORTED and "recovery" in nav.text


def test_a_goal_that_is_not_finite_is_aborted_at_once():
    # A NaN yaw used to leave the robot turning on the spot at the goal for ever.
    for goal in [(2.0, 1.0, math.nan), (math.inf, 1.0, 0.0)]:
        nav = Navigator(goal)
        drive(nav, (0.0, 0.0, 0.0), straight_plan, seconds=1.0)
        assert nav.status == ABORTED and "is not finite" in nav.text, goal
