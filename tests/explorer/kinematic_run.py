"""A ROS-free exploration run that drives the explorer through its whole interface, as the
node does (plan_inputs, the known area and a blocked start handed back with each plan),
on kinematic_sim's world, sensor and mapper. Also loads the procedural family worlds
(walls, boxes, cylinders) without the simulator."""

import math
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(REPO / "catkin_ws" / "src" / "explorer" / "src"))
sys.path.insert(0, str(REPO / "catkin_ws" / "src" / "bullet_turtlebot" / "src"))

from bullet_turtlebot import world_check  # noqa: E402
from bullet_turtlebot.world_families import generate  # noqa: E402
from bullet_turtlebot.world_file import write_world  # noqa: E402
from kinematic_sim import KINECT, GridWorld, KinematicBase, RunResult  # noqa: E402


def family_world(family, seed, folder):
    """(GridWorld with the world's walls and primitives, start pose) of a family world
    written into `folder`."""
    path = write_world(Path(folder), generate(family, seed))
    grid = world_check.load_grid(path)
    world = GridWorld(grid.occupied, grid.resolution, grid.origin[0], grid.origin[1])
    return world, tuple(grid.start)


def explore(
    world,
    start,
    seconds,
    explorer,
    planner,
    dt=0.1,
    map_period=2.0,
    scan_period=0.2,
    robot_radius=0.18,
    update=(0.5, 0.436),
    on_step=None,
    laser=KINECT,
):
    """Like kinematic_sim.explore, but the map is published only when the mapper
    integrated a scan since the last one (gmapping publishes after processing a scan, so
    a robot standing still gets no new map), and the explorer gets everything the node
    gives it. `on_step(now, explorer, mapper, reachable)` is called after each control
    step. `laser`: kinematic_sim.Laser (the Kinect by default)."""
    robot = KinematicBase(world, start, robot_radius, update, laser)
    next_map = next_scan = 0.0
    map_stamp = None
    integrated = False
    ahead = math.inf
    now = 0.0
    while now < seconds:
        if now >= next_scan:
            ahead, scan_integrated = robot.scan()
            integrated = integrated or scan_integrated
            next_scan += scan_period
        if now >= next_map and integrated:
            planner.set_map(
                robot.mapper.occupancy(), world.resolution, world.origin_x, world.origin_y
            )
            map_stamp = now
            next_map = now + map_period
            integrated = False
        if explorer.wants_plan(now, map_stamp):
            plan = planner.plan(robot.x, robot.y, **explorer.plan_inputs(now, map_stamp))
            explorer.accept_plan(
                plan,
                now,
                map_stamp,
                known_area=planner.known_free_area(),
                start_blocked=planner.start_blocked,
            )
        linear, angular = explorer.control(now, robot.x, robot.y, robot.yaw, ahead)
        robot.drive(linear, angular, dt, explorer, now)
        now += dt
        if on_step is not None:
            on_step(now, explorer, robot.mapper, robot.reachable)
        if explorer.done:
            break
    return RunResult(
        robot.coverage(),
        now,
        robot.travelled,
        robot.collisions,
        explorer.done,
        explorer.goals_reached,
        {},
    )


def main(argv=None):
    """Coverage over time of one family world, e.g. the wide laser under live SLAM's
    Turtlebot tuning: `kinematic_run.py warehouse 1 300 --laser wide-turtlebot-slam`."""
    import argparse
    import tempfile
    import time

    from explorer.exploration import Explorer
    from explorer.map_planner import MapPlanner
    from kinematic_sim import KINECT, WIDE, WIDE_TURTLEBOT_SLAM

    lasers = {"kinect": KINECT, "wide": WIDE, "wide-turtlebot-slam": WIDE_TURTLEBOT_SLAM}
    parser = argparse.ArgumentParser(description=main.__doc__)
    parser.add_argument("family")
    parser.add_argument("seed", type=int)
    parser.add_argument("seconds", type=float)
    parser.add_argument("--laser", choices=sorted(lasers), default="kinect")
    args = parser.parse_args(argv)
    marks = {}

    def on_step(now, explorer, mapper, reachable):
        mark = 150 * int(now // 150)
        if mark and mark not in marks:
            marks[mark] = float((mapper.known() & reachable).sum() / reachable.sum())

    with tempfile.TemporaryDirectory() as folder:
        world, start = family_world(args.family, args.seed, folder)
        explorer = Explorer()
        wall = time.monotonic()
        result = explore(
            world,
            start,
            args.seconds,
            explorer,
            MapPlanner(),
            on_step=on_step,
            laser=lasers[args.laser],
        )
    at = ", ".join(f"{m} s {c:.1%}" for m, c in sorted(marks.items()))
    print(
        f"{args.family}_{args.seed} {args.laser}: coverage {result.coverage:.1%} at "
        f"{result.sim_time:.0f} s ({at}); travelled {result.travelled:.0f} m, "
        f"{result.goals} goals, done {result.done}, {time.monotonic() - wall:.0f} s wall"
    )


if __name__ == "__main__":
    main()
