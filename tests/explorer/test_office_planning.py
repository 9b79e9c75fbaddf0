"""The planner on the office world's map (no ROS): a partially known office as the robot
would have mapped it from its start, then a whole exploration with a kinematic robot, a
Kinect-like sensor and a map that integrates scans the way gmapping does."""

import math
import sys
from pathlib import Path

import numpy as np
import pytest

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parents[1] / "catkin_ws" / "src" / "explorer" / "src"))

from explorer.exploration import Explorer  # noqa: E402
from explorer.map_planner import MapPlanner  # noqa: E402
from kinematic_sim import REPO, WORLDS, GridWorld, Mapper, cast_fan, explore  # noqa: E402

START = (-8.5, 0.0, 0.0)  # the office world's start pose


def spin_map(world, x, y):
    """The map after turning round once at (x, y): what the robot knows at first."""
    mapper = Mapper(world)
    for k in range(24):
        yaw = k * math.pi / 12
        sx, sy = x - 0.087 * math.cos(yaw), y - 0.087 * math.sin(yaw)
        angles, ranges = cast_fan(world, sx, sy, yaw)
        mapper.integrate(sx, sy, yaw, angles, ranges)
    return mapper


@pytest.fixture(scope="module")
def office():
    return GridWorld.from_yaml(WORLDS / "office.yaml")


def test_first_goal_on_a_partially_known_office(office):
    mapper = spin_map(office, *START[:2])
    known = mapper.known()
    assert 0.05 < known.mean() < 0.5  # partially known
    planner = MapPlanner()
    planner.set_map(mapper.occupancy(), office.resolution, office.origin_x, office.origin_y)
    assert planner.frontier_count >= 2
    plan = planner.plan(*START[:2])
    assert plan is not None
    # The path starts at the robot, ends at the goal and keeps the robot's body off the
    # real walls (ground truth, not the map).
    assert plan.path[0] == pytest.approx(START[:2])
    assert plan.path[-1] == pytest.approx(plan.goal, abs=1e-9)
    clearance = office.clearance()
    rows, cols = office.cell(plan.path[1:, 0], plan.path[1:, 1])
    assert clearance[rows, cols].min() >= 0.18
    # The goal lies in known free space, and it sees the unknown it was chosen for.
    row, col = office.cell(*plan.goal)
    assert known[row, col] and not office.occupied[row, col]
    tx, ty = plan.target
    assert 0.6 - 0.15 <= math.hypot(tx - plan.goal[0], ty - plan.goal[1]) <= 2.5 + 0.15
    assert plan.look_yaws and plan.gain >= 1.0


def test_blacklisted_and_viewed_frontiers_change_the_choice(office):
    mapper = spin_map(office, *START[:2])
    planner = MapPlanner()
    planner.set_map(mapper.occupancy(), office.resolution, office.origin_x, office.origin_y)
    first = planner.plan(*START[:2])
    second = planner.plan(*START[:2], excluded_points=[first.goal])
    assert math.dist(second.goal, first.goal) > planner.params.blacklist_radius
    third = planner.plan(*START[:2], dead_frontiers=[first.target])
    assert math.dist(third.target, first.target) > 0.5


def test_nothing_to_explore_in_a_fully_known_office(office):
    truth = np.where(office.occupied, 100, 0).astype(np.int8)
    planner = MapPlanner()
    planner.set_map(truth, office.resolution, office.origin_x, office.origin_y)
    assert planner.plan(*START[:2]) is None


@pytest.mark.parametrize(
    "world_file",
    [WORLDS / "office.yaml", REPO / "maps" / "office.yaml"],
    ids=["walls", "furnished"],
)
def test_kinematic_exploration_covers_the_office(world_file):
    """400 s of exploring from the office's start: most of the free area gets mapped, and
    the robot hardly ever touches anything (ground truth clearance, bumper emulated)."""
    if not world_file.exists():
        pytest.skip(f"{world_file} is missing")
    world = GridWorld.from_yaml(world_file)
    result = explore(world, START, 400.0, Explorer(), MapPlanner())
    figures = ", ".join(f"{t} s {c:.0%}" for t, c in sorted(result.coverage_at.items()))
    contact = result.collisions * 0.1 / result.sim_time
    print(
        f"{world_file.name}: {figures}; {result.travelled:.0f} m, {result.goals} goals, "
        f"contact {contact:.1%}"
    )
    assert result.coverage >= 0.80
    assert contact < 0.01
