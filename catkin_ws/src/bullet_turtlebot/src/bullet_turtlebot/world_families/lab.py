"""lab: a cluttered laboratory. Benches, cabinets, gas bottles and stools; glass-like
partitions split it into a main lab and two bays, with doors and see-through gaps (0.2-0.3 m:
the laser sees through them, the robot cannot pass)."""

from bullet_turtlebot.world_families.layout import Layout, free_centre, pick, snap
from bullet_turtlebot.world_file import BLUE, GREY, RED

SIZE = ((12.0, 20.0), (10.0, 16.0))  # width, height ranges (m)
DOOR_WIDTHS = (0.9, 1.2)
GAP_WIDTHS = (0.2, 0.3)
CLUTTER_GAP = 0.6  # m: benches and bottles stand closer together than furniture elsewhere
WHITE = (0.85, 0.85, 0.8)


def build(rng):
    width, height = pick(rng, 12.0, 20.0, 0.5), pick(rng, 10.0, 16.0, 0.5)
    partition_x = snap(pick(rng, 0.45 * width, 0.6 * width, 0.05))
    bays_y = snap(pick(rng, 0.4 * height, 0.6 * height, 0.05))
    layout = Layout(width, height)
    layout.set_start(round(partition_x - 3.0, 3), snap(0.3 * height), 0.0)
    # Along the west partition: a door into each bay, gaps anywhere but at the junction.
    doors = [
        (free_centre(rng, 0.45, bays_y - 0.35, door, [], 0), door)
        for door in [pick(rng, *DOOR_WIDTHS, 0.1)]
    ]
    door = pick(rng, *DOOR_WIDTHS, 0.1)
    doors.append((free_centre(rng, bays_y + 0.35, height - 0.45, door, [], 0), door))
    junction = [(bays_y, 0.2)]
    gaps = see_through(rng, 0.55, height - 0.55, rng.randint(2, 4), doors + junction)
    layout.wall(partition_x, 0.0, partition_x, height, doors=doors, gaps=gaps)
    # Between the bays: sometimes a door, always a gap or more.
    between = []
    if rng.random() < 0.5:
        door = pick(rng, *DOOR_WIDTHS, 0.1)
        between.append((free_centre(rng, partition_x + 0.35, width - 0.45, door, [], 0), door))
    gaps = see_through(rng, partition_x + 0.45, width - 0.55, rng.randint(1, 3), between)
    layout.wall(partition_x, bays_y, width, bays_y, doors=between, gaps=gaps)
    main = layout.interior(0.0, 0.0, partition_x, height)
    furnish(rng, layout, main, benches=rng.randint(3, 5), islands=rng.randint(1, 3))
    for y0, y1 in ((0.0, bays_y), (bays_y, height)):
        bay = layout.interior(partition_x, y0, width, y1)
        furnish(rng, layout, bay, benches=rng.randint(2, 3), islands=rng.randint(0, 1))
    return layout, (
        f"{len(layout.boxes)} boxes, {len(layout.cylinders)} cylinders, "
        f"{len(layout.gaps)} see-through gaps"
    )


def see_through(rng, lo, hi, count, openings):
    """Up to count gaps of 0.2-0.3 m, 0.4 m or more from each other and the doors."""
    gaps = []
    for _ in range(count):
        gap = pick(rng, *GAP_WIDTHS, 0.05)
        centre = free_centre(rng, lo, hi, gap, openings + gaps, 0.4)
        if centre is not None:
            gaps.append((centre, gap))
    return gaps


def furnish(rng, layout, room, benches, islands):
    for _ in range(benches):  # wall benches
        size = (pick(rng, 1.6, 3.2, 0.2), pick(rng, 0.7, 0.8, 0.1))
        layout.place_box(rng, room, size, 0.9, WHITE, gap=CLUTTER_GAP)
    for _ in range(islands):
        size = (pick(rng, 2.0, 3.2, 0.2), pick(rng, 0.8, 1.2, 0.2))
        layout.place_box(rng, room, size, 0.9, WHITE, flush=False, gap=CLUTTER_GAP)
    if rng.random() < 0.6:  # fume hood or tall cabinet
        layout.place_box(rng, room, (pick(rng, 1.2, 1.8, 0.2), 0.8), 2.2, GREY, gap=CLUTTER_GAP)
    for _ in range(rng.randint(2, 5)):  # gas bottles
        radius = pick(rng, 0.1, 0.15, 0.05)
        layout.place_cylinder(rng, room, radius, 1.5, RED, gap=CLUTTER_GAP)
    for _ in range(rng.randint(2, 4)):  # stools and bins
        layout.place_cylinder(rng, room, 0.2, 0.6, BLUE, flush=False, gap=CLUTTER_GAP)
