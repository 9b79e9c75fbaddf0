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
from kinematic_sim import (  # noqa: E402
    CAMERA_X,
    GridWorld,
    Mapper,
    RunResult,
    _clearance,
    _coverage,
    cast_fan,
)


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
):
    """Like kinematic_sim.explore, but the map is published only when the mapper
    integrated a scan since the last one (gmapping publishes after processing a scan, so
    a robot standing still gets no new map), and the explorer gets everything the node
    gives it. `on_step(now, explorer, mapper, reachable)` is called after each control
    step."""
    x, y, yaw = start
    last_update = (x, y, yaw, True)
    mapper = Mapper(world)
    reachable = world.free_region(x, y)
    clearance_grid = world.clearance()
    travelled, collisions = 0.0, 0
    next_map = next_scan = 0.0
    map_stamp = None
    integrated = False
    ahead = math.inf
    now = 0.0
    while now < seconds:
        if now >= next_scan:
            sx, sy = x + CAMERA_X * math.cos(yaw), y + CAMERA_X * math.sin(yaw)
            angles, ranges = cast_fan(world, sx, sy, yaw)
            moved = math.hypot(x - last_update[0], y - last_update[1])
            turned = abs(math.remainder(yaw - last_update[2], 2 * math.pi))
            if moved >= update[0] or turned >= update[1] or last_update[3]:
                mapper.integrate(sx, sy, yaw, angles, ranges)
                last_update = (x, y, yaw, False)
                integrated = True
            ahead = _clearance(angles, ranges, robot_radius)
            next_scan += scan_period
        if now >= next_map and integrated:
            planner.set_map(mapper.occupancy(), world.resolution, world.origin_x, world.origin_y)
            map_stamp = now
            next_map = now + map_period
            integrated = False
        if explorer.wants_plan(now, map_stamp):
            plan = planner.plan(x, y, **explorer.plan_inputs(now, map_stamp))
            explorer.accept_plan(
                plan,
                now,
                map_stamp,
                known_area=planner.known_free_area(),
                start_blocked=planner.start_blocked,
            )
        linear, angular = explorer.control(now, x, y, yaw, ahead)
        nx = x + linear * math.cos(yaw) * dt
        ny = y + linear * math.sin(yaw) * dt
        row, col = world.cell(nx, ny)
        if clearance_grid[row, col] < robot_radius:
            collisions += 1
            explorer.bumped(now)
        else:
            travelled += math.hypot(nx - x, ny - y)
            x, y = nx, ny
        yaw = math.atan2(math.sin(yaw + angular * dt), math.cos(yaw + angular * dt))
        now += dt
        if on_step is not None:
            on_step(now, explorer, mapper, reachable)
        if explorer.done:
            break
    return RunResult(
        _coverage(mapper, reachable),
        now,
        travelled,
        collisions,
        explorer.done,
        explorer.goals_reached,
        {},
    )
