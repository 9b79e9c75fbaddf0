"""hospital: one long double-loaded corridor (rooms on both sides) with many similar doors.

All rooms have the same width and door; doors sit near alternate partitions, so they pair
up as in real wards. A few partitions are left out (double rooms with two doors) and a few
doors are double doors. Long, self-similar corridors are what makes this hard for SLAM.
"""

from bullet_turtlebot.world_families.layout import Layout, Rect, pick, snap
from bullet_turtlebot.world_file import BLUE, GREY, WALL

SIZE = ((30.0, 40.0), (10.0, 13.8))  # width, height ranges (m)
DOOR_WIDTHS = (1.0, 1.8)  # single doors 1.0-1.3 m, double doors 1.6-1.8 m
WHITE = (0.85, 0.85, 0.8)


def build(rng):
    width = pick(rng, 30.0, 40.0, 1.0)
    corridor = pick(rng, 2.0, 2.8, 0.2)
    depth = pick(rng, 4.0, 5.5, 0.5)
    height = round(2 * depth + corridor, 3)
    count = round(width / pick(rng, 3.2, 4.2, 0.1))  # rooms per side
    door = pick(rng, 1.0, 1.3, 0.1)
    inset = pick(rng, 0.3, 0.6, 0.05)  # partition to the nearer jamb
    layout = Layout(width, height)
    layout.set_start(1.2, round(depth + corridor / 2, 3), 0.0)
    cuts = [snap(i * width / count) for i in range(count)] + [width]
    for wall_y, y0, y1 in ((depth, 0.0, depth), (depth + corridor, depth + corridor, height)):
        doors = []
        for i, (x0, x1) in enumerate(zip(cuts, cuts[1:], strict=False)):
            wide = pick(rng, 1.6, 1.8, 0.2) if rng.random() < 0.1 else door
            jamb = max(x0, WALL) + inset if i % 2 == 0 else min(x1, width - WALL) - inset - wide
            doors.append((snap(jamb + wide / 2), wide))
        layout.wall(0.0, wall_y, width, wall_y, doors=doors)
        rooms = [cuts[0]]
        for x in cuts[1:-1]:
            if rng.random() < 0.15 and x - rooms[-1] < 5.0:
                continue  # a double room: no partition here
            layout.wall(x, y0, x, y1)
            rooms.append(x)
        rooms.append(width)
        for x0, x1 in zip(rooms, rooms[1:], strict=False):
            furnish_room(rng, layout, layout.interior(x0, y0, x1, y1))
    hall = Rect(WALL, depth + 0.05, width - WALL, depth + corridor - 0.05)
    for _ in range(rng.randint(2, 5)):  # trolleys and benches along the corridor walls
        layout.place_box(rng, hall, (pick(rng, 0.8, 1.6, 0.2), 0.5), 0.9, GREY)
    return layout, f"a {corridor:g} m wide corridor, {2 * count} rooms, {door:g} m doors"


def furnish_room(rng, layout, room):
    layout.place_box(rng, room, (pick(rng, 1.9, 2.1, 0.1), pick(rng, 0.9, 1.0, 0.1)), 0.6, WHITE)
    layout.place_box(rng, room, (0.45, 0.45), 0.8, WHITE)  # bedside cabinet
    if rng.random() < 0.5:  # wardrobe
        layout.place_box(rng, room, (1.0, 0.6), 2.0, GREY)
    layout.place_cylinder(rng, room, 0.25, 0.9, BLUE, flush=False)  # chair
