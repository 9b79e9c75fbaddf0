#!/usr/bin/python3
"""Per-plan CPU cost of the explorer on the office world (no ROS): prepare a half-explored
office map (crop, downsample, inflate, frontiers, gain) and plan from the start.

    /usr/bin/python3 catkin_ws/src/explorer/bench/bench_planner.py
Prints milliseconds per map update and per plan, and what that costs at sim speed 8
with a map every 2 s and a plan every 3 s of sim time."""

import math
import statistics
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[3]
sys.path.insert(0, str(HERE.parent / "src"))
sys.path.insert(0, str(REPO / "tests" / "explorer"))

from explorer.map_planner import MapPlanner  # noqa: E402
from kinematic_sim import GridWorld, Mapper, cast_fan  # noqa: E402


def main():
    world = GridWorld.from_yaml(REPO / "maps" / "office.yaml")
    mapper = Mapper(world)
    for x in (-8.5, -5.0, -2.0, 1.0):
        for k in range(12):
            yaw = k * math.pi / 6
            angles, ranges = cast_fan(world, x, 0.0, yaw)
            mapper.integrate(x, 0.0, yaw, angles, ranges)
    data = mapper.occupancy()
    planner = MapPlanner()
    prepare, plan = [], []
    for _ in range(15):
        t0 = time.perf_counter()
        planner.set_map(data, world.resolution, world.origin_x, world.origin_y)
        t1 = time.perf_counter()
        planner.plan(-8.5, 0.0)
        t2 = time.perf_counter()
        prepare.append(t1 - t0)
        plan.append(t2 - t1)
    p, q = statistics.median(prepare) * 1e3, statistics.median(plan) * 1e3
    shape = planner.prepared.classes.shape
    print(f"office map {data.shape[1]}x{data.shape[0]} cells, planning grid {shape[1]}x{shape[0]}")
    print(f"map update: {p:.1f} ms   plan: {q:.1f} ms   (median of 15)")
    speed = 8.0
    per_wall_second = speed * (p / 2.0 + q / 3.0) / 1e3
    print(f"at sim speed {speed:g}: {per_wall_second:.0%} of one core")


if __name__ == "__main__":
    main()
