"""Chapter 10's figures: goals for a navigation run on a grid, the shortest path to each,
and how well the robot did against the simulator's ground truth (numpy and scipy, no ROS).

A grid here is bullet_turtlebot's world_check.Grid (occupied cells, resolution, origin,
start): a world's own (the bench) or a saved map's, where unknown cells count as solid
(`grid_of_saved_map`). Paths run through cells at least the robot's radius from a solid,
8-connected; goals keep at least the costmap's inflation radius from one.
"""

import heapq
import math
import random
import statistics

import numpy as np
from bullet_turtlebot.world_check import ROBOT_RADIUS, Grid, clearance
from scipy import ndimage

from rosbook_eval.poses import compose, position_errors, rms, wrap

SQRT2 = math.sqrt(2.0)
# s: how far a goal's end may lie outside the recorded ground truth and still be scored at
# the nearest pose (the recorder starts and stops a message or two apart from the goals).
CLOCK_SLACK = 1.0


def grid_of_saved_map(cells, resolution, origin, start=(0.0, 0.0, 0.0)):
    """A saved map (OccupancyGrid order: row 0 at the bottom; -1 unknown, 0 free, 100
    occupied; origin unrotated) as a Grid: anything not known free is solid. `start`: the
    robot's pose on the map (a SLAM map's frame is where the mapping run began)."""
    if abs(origin[2]) > 1e-6:
        raise ValueError("maps with a rotated origin are not supported")
    return Grid(np.asarray(cells) != 0, float(resolution), tuple(origin[:2]), tuple(start))


def passable_region(clear, start_cell, radius):
    """Cells whose centre is at least `radius` from any solid (`clear`: world_check's
    clearance of each cell), 8-connected to the start cell."""
    ok = clear >= radius
    labels, _ = ndimage.label(ok, structure=np.ones((3, 3)))
    start = labels[start_cell] if _inside(ok, start_cell) else 0
    return labels == start if start else np.zeros_like(ok)


def _inside(array, cell):
    return 0 <= cell[0] < array.shape[0] and 0 <= cell[1] < array.shape[1]


def path_lengths(region, resolution, source):
    """Shortest 8-connected path length (m) from cell `source` to every cell of `region`
    (inf where unreachable): Dijkstra on the grid."""
    rows, cols = region.shape
    dist = np.full(region.shape, np.inf)
    dist[source] = 0.0
    heap = [(0.0, source)]
    steps = [
        (di, dj, resolution * (SQRT2 if di and dj else 1.0))
        for di in (-1, 0, 1)
        for dj in (-1, 0, 1)
        if di or dj
    ]
    while heap:
        d, (i, j) = heapq.heappop(heap)
        if d > dist[i, j]:
            continue
        for di, dj, cost in steps:
            ni, nj = i + di, j + dj
            if 0 <= ni < rows and 0 <= nj < cols and region[ni, nj] and d + cost < dist[ni, nj]:
                dist[ni, nj] = d + cost
                heapq.heappush(heap, (d + cost, (ni, nj)))
    return dist


def pick_goals(grid, count, goal_clearance, min_leg, seed=None, near=None, near_radius=0.5):
    """`count` goals (x, y, yaw), each with its shortest path length (m) from the previous
    pose (the grid's start first): [((x, y, yaw), length), ...], fewer if the reachable
    space runs out. With a seed, each goal is a random reachable cell at least `min_leg`
    of path from the previous one; without, the goals spread out: each is the reachable
    cell farthest (in straight line) from the start and the goals so far, and faces away
    from where the robot comes from. `near` ((x, y) points, e.g. where the robot drove
    while it made the map): goals only within `near_radius` of one of them."""
    clear = clearance(grid)  # one distance transform for both masks
    here = grid.cell(*grid.start[:2])
    region = passable_region(clear, here, ROBOT_RADIUS)
    if not region.any():
        raise ValueError(
            f"the start ({grid.start[0]:.2f}, {grid.start[1]:.2f}) is not in free space "
            f"{ROBOT_RADIUS} m from any obstacle or unknown cell"
        )
    roomy = region & (clear >= goal_clearance)
    if near is not None:
        roomy &= within(grid, near, near_radius)
    rng = random.Random(seed)
    visited = [here]
    goals = []
    for _ in range(count):
        dist = path_lengths(region, grid.resolution, here)
        reachable = roomy & np.isfinite(dist)
        candidates = np.argwhere(reachable & (dist >= min_leg))
        if not len(candidates):
            candidates = np.argwhere(reachable & (dist > 0))
        if not len(candidates):
            break
        if seed is not None:
            i, j = candidates[rng.randrange(len(candidates))]
            yaw = rng.uniform(-math.pi, math.pi)
        else:
            spread = np.full(len(candidates), np.inf)
            for vi, vj in visited:
                spread = np.minimum(spread, np.hypot(candidates[:, 0] - vi, candidates[:, 1] - vj))
            i, j = candidates[int(np.argmax(spread))]
            yaw = math.atan2(i - here[0], j - here[1])
        x = grid.origin[0] + (j + 0.5) * grid.resolution
        y = grid.origin[1] + (i + 0.5) * grid.resolution
        goals.append(((round(x, 3), round(y, 3), round(yaw, 3)), float(dist[i, j])))
        here = (int(i), int(j))
        visited.append(here)
    return goals


def within(grid, points, radius):
    """Cells whose centre is within `radius` of one of `points` ((x, y) in the grid's frame)."""
    marks = np.zeros(grid.occupied.shape, dtype=bool)
    for x, y in np.asarray(points, dtype=float).reshape(-1, 2):
        cell = grid.cell(x, y)
        if _inside(marks, cell):
            marks[cell] = True
    if not marks.any():
        return marks
    return ndimage.distance_transform_edt(~marks) * grid.resolution <= radius


def score_navigation(truth, estimate, goals, map_frame, top_speed):
    """Figures of a navigation run, all against the ground truth:

    - `truth`: the true base pose in the world (poses.Trajectory);
    - `estimate`: the robot's own pose on the map while it drove (amcl's map→odom ∘
      odometry, bag_tracks.live_slam_track), a Trajectory;
    - `goals`: one dict per goal sent: goal (x, y, yaw on the map), state (actionlib's name),
      sent and ended (sim s), path_m (shortest path from the previous goal, m);
    - `map_frame`: the world pose of the map's frame (the mapping score's placement);
    - `top_speed`: move_base's max_vel_x (m/s): the ideal time is path_m at that speed.

    Returns {goals, reached, localization_rms_m, localization_max_m, time_ratio_median,
    position_error_max_m, heading_error_max_rad, per_goal: [...]} with each goal's
    position and heading error where it ended, in the world.
    """
    per_goal = []
    for n, g in enumerate(goals, 1):
        gx, gy, gyaw = compose(map_frame, tuple(g["goal"]))
        if not truth.t[0] - CLOCK_SLACK <= g["ended"] <= truth.t[-1] + CLOCK_SLACK:
            raise ValueError(
                f"goal {n} ended at {g['ended']:.1f} s, outside the ground truth's "
                f"{truth.t[0]:.1f}-{truth.t[-1]:.1f} s: were its times read off another clock "
                "(wall time instead of the simulator's)?"
            )
        ended = min(max(g["ended"], truth.t[0]), truth.t[-1])
        tx, ty, tyaw = truth.at(ended)
        ideal = g["path_m"] / top_speed
        seconds = g["ended"] - g["sent"]
        reached = g["state"] == "SUCCEEDED"
        per_goal.append(
            {
                "goal": list(g["goal"]),
                "state": g["state"],
                "sim_seconds": seconds,
                "ideal_seconds": ideal,
                "time_ratio": seconds / ideal if reached and ideal > 0 else None,
                "position_error_m": math.hypot(tx - gx, ty - gy),
                "heading_error_rad": abs(wrap(tyaw - gyaw)),
            }
        )
    driving = estimate.select(truth.covers(estimate.t))
    errors = position_errors(driving.transformed(map_frame), truth)
    done = [g for g in per_goal if g["state"] == "SUCCEEDED"]
    ratios = [g["time_ratio"] for g in done if g["time_ratio"] is not None]
    return {
        "goals": len(per_goal),
        "reached": len(done),
        "localization_rms_m": rms(errors),
        "localization_max_m": float(errors.max()) if len(errors) else float("nan"),
        "time_ratio_median": statistics.median(ratios) if ratios else None,
        "position_error_max_m": max((g["position_error_m"] for g in done), default=None),
        "heading_error_max_rad": max((g["heading_error_rad"] for g in done), default=None),
        "per_goal": per_goal,
    }


def leg_lengths(grid, goals):
    """Shortest path length (m) of each leg: the grid's start to the first goal, then goal
    to goal; inf for a goal the robot cannot reach on this grid."""
    region = passable_region(clearance(grid), grid.cell(*grid.start[:2]), ROBOT_RADIUS)
    here, lengths = grid.cell(*grid.start[:2]), []
    for x, y, _ in goals:
        cell = grid.cell(x, y)
        if not _inside(region, here) or not region[here]:
            lengths.append(math.inf)
        else:
            dist = path_lengths(region, grid.resolution, here)
            lengths.append(float(dist[cell]) if _inside(region, cell) else math.inf)
        here = cell
    return lengths
