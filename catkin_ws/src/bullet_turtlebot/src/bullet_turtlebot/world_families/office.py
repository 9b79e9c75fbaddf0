"""office: rooms on both sides of a corridor, doors of varying width, an open-plan area at
the corridor's far end; some rooms connect to their neighbour or to the open-plan area."""

from bullet_turtlebot.world_families.layout import Layout, Rect, free_centre, pick, split
from bullet_turtlebot.world_file import BLUE, GREEN, GREY, WOOD

SIZE = ((18.0, 28.0), (9.8, 15.4))  # width, height ranges (m)
DOOR_WIDTHS = (0.9, 1.4)


def build(rng):
    width = pick(rng, 18.0, 28.0, 0.5)
    open_plan = pick(rng, 4.0, 7.0, 0.5)
    south, north = pick(rng, 4.0, 6.5, 0.5), pick(rng, 4.0, 6.5, 0.5)
    corridor = pick(rng, 1.8, 2.4, 0.1)
    height = round(south + corridor + north, 3)
    layout = Layout(width, height)
    layout.set_start(1.2, round(south + corridor / 2, 3), 0.0)
    rooms_end = width - open_plan
    rooms = 0
    for wall_y, y0, y1 in ((south, 0.0, south), (south + corridor, south + corridor, height)):
        cuts = split(rng, 0.0, rooms_end, 3.5, 7.0)
        doors = []
        for x0, x1 in zip(cuts, cuts[1:], strict=False):
            door = pick(rng, *DOOR_WIDTHS, 0.1)
            doors.append((free_centre(rng, x0 + 0.45, x1 - 0.35, door, [], 0), door))
        layout.wall(0.0, wall_y, rooms_end, wall_y, doors=doors)
        for x in cuts[1:-1]:  # partitions, some with a door to the next room
            layout.wall(x, y0, x, y1, doors=side_door(rng, y0, y1, 0.3))
        layout.wall(rooms_end, y0, rooms_end, y1, doors=side_door(rng, y0, y1, 0.5))
        for x0, x1 in zip(cuts, cuts[1:], strict=False):
            furnish_room(rng, layout, layout.interior(x0, y0, x1, y1))
        rooms += len(cuts) - 1
    corridor_mouth = Rect(rooms_end - 1.0, south, rooms_end + 1.0, south + corridor)
    layout.keep_out.append(corridor_mouth)  # the open-plan area's west side is open there
    furnish_open_plan(rng, layout, layout.interior(rooms_end, 0.0, width, height))
    return layout, f"a {corridor:g} m corridor, {rooms} rooms, an open-plan area"


def side_door(rng, y0, y1, chance):
    if rng.random() >= chance:
        return []
    door = pick(rng, 0.9, 1.1, 0.1)
    return [(free_centre(rng, y0 + 0.45, y1 - 0.45, door, [], 0), door)]


def furnish_room(rng, layout, room):
    layout.place_box(rng, room, (pick(rng, 1.2, 1.8, 0.1), pick(rng, 0.6, 0.8, 0.1)), 0.75, WOOD)
    if rng.random() < 0.6:  # bookcase
        layout.place_box(rng, room, (pick(rng, 0.8, 2.0, 0.2), 0.4), 1.8, WOOD)
    if rng.random() < 0.4:  # filing cabinet
        layout.place_box(rng, room, (0.5, 0.5), 1.0, GREY)
    if rng.random() < 0.4:  # meeting table
        size = (pick(rng, 1.0, 1.6, 0.2), 0.8)
        layout.place_box(rng, room, size, 0.75, WOOD, flush=False)
    for _ in range(rng.randint(0, 2)):  # plants and bins
        radius = pick(rng, 0.15, 0.3, 0.05)
        layout.place_cylinder(rng, room, radius, pick(rng, 0.6, 1.2, 0.1), GREEN)


def furnish_open_plan(rng, layout, area):
    for _ in range(rng.randint(2, 4)):  # desk clusters
        size = (pick(rng, 1.6, 3.2, 0.2), pick(rng, 1.2, 1.6, 0.2))
        layout.place_box(rng, area, size, 0.75, WOOD, flush=False, gap=0.8)
    for _ in range(rng.randint(1, 2)):  # sofas and cupboards
        layout.place_box(rng, area, (pick(rng, 1.4, 2.2, 0.2), 0.8), 0.8, GREY)
    for _ in range(rng.randint(1, 3)):
        layout.place_cylinder(rng, area, pick(rng, 0.2, 0.3, 0.05), 1.0, BLUE)
