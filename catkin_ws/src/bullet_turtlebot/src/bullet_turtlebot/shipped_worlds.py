"""The hand-made shipped worlds: playground, maze and office (their bytes must not change)."""

import random

from bullet_turtlebot.world_file import BLUE, GREEN, GREY, RED, WALL, WOOD, Plan, World


def playground():
    """An open 12 x 10 m room with furniture: the Gazebo playground stand-in."""
    plan = Plan(12.0, 10.0)
    plan.outline()
    plan.vwall(8.0, 6.5, 10.0)  # a partial partition
    boxes = [
        ((-2.5, 4.6, 0.0), (2.0, 0.4, 1.8), WOOD),  # bookcase against the north wall
        ((3.0, 2.0, 0.3), (1.6, 0.8, 0.75), WOOD),  # table
        ((-3.5, -2.5, 0.0), (0.8, 0.8, 0.8), RED),  # crate
        ((0.0, -3.8, 0.0), (3.0, 0.5, 0.9), GREY),  # cabinet along the south wall
        ((4.5, -2.5, 0.6), (0.6, 0.6, 0.5), GREEN),  # low box
        ((-5.2, 1.0, 0.0), (0.6, 2.0, 1.2), WOOD),  # shelf along the west wall
    ]
    cylinders = [
        ((2.5, -1.0), 0.3, 1.0, BLUE),  # barrels
        ((-1.5, 1.8), 0.25, 0.9, RED),
        ((-2.0, -0.8), 0.2, 1.5, GREY),  # a pillar-like post
        ((5.0, 3.5), 0.35, 0.8, GREEN),
    ]
    return World(
        "playground",
        plan,
        origin=(-6.0, -5.0, 0.0),
        start=(0.0, 0.0, 0.0),
        boxes=boxes,
        cylinders=cylinders,
        comment="playground: open room with furniture (stands in for Gazebo's playground)",
    )


def maze():
    """A 7 x 7 cell maze of 1.5 m corridors with a few loops: the Stage stand-in."""
    cells, size = 7, 1.5
    plan = Plan(cells * size, cells * size)
    plan.outline()
    rng = random.Random(2014)
    # Walls between cells: east[r][c] separates (r, c) and (r, c + 1); north likewise.
    east = [[True] * cells for _ in range(cells)]
    north = [[True] * cells for _ in range(cells)]
    seen = {(0, 0)}
    stack = [(0, 0)]
    while stack:
        r, c = stack[-1]
        options = [
            (r + dr, c + dc)
            for dr, dc in ((1, 0), (-1, 0), (0, 1), (0, -1))
            if 0 <= r + dr < cells and 0 <= c + dc < cells and (r + dr, c + dc) not in seen
        ]
        if not options:
            stack.pop()
            continue
        nr, nc = rng.choice(options)
        if nr == r:
            east[r][min(c, nc)] = False
        else:
            north[min(r, nr)][c] = False
        seen.add((nr, nc))
        stack.append((nr, nc))
    for _ in range(6):  # loops make it a fairer SLAM test
        r, c = rng.randrange(cells - 1), rng.randrange(cells - 1)
        if rng.random() < 0.5:
            east[r][c] = False
        else:
            north[r][c] = False
    for r in range(cells):
        for c in range(cells):
            if c < cells - 1 and east[r][c]:
                plan.vwall((c + 1) * size, r * size - WALL / 2, (r + 1) * size + WALL / 2)
            if r < cells - 1 and north[r][c]:
                plan.hwall(c * size - WALL / 2, (c + 1) * size + WALL / 2, (r + 1) * size)
    return World(
        "maze",
        plan,
        origin=(0.0, 0.0, 0.0),
        start=(0.75, 0.75, 0.0),
        comment="maze: 10.5 x 10.5 m, 1.5 m corridors (stands in for turtlebot_stage's maze)",
    )


def office():
    """A 20 x 15 m office: a long corridor, rooms on both sides, doors, furniture."""
    width, height = 20.0, 15.0
    plan = Plan(width, height)
    plan.outline()
    corridor_low, corridor_high = 6.5, 8.5
    door = 1.0
    # Rooms north of the corridor: four 5 m rooms; south: 7 + 6 + 7 m rooms.
    for y, splits in ((corridor_high, (0, 5, 10, 15, 20)), (corridor_low, (0, 7, 13, 20))):
        for x0, x1 in zip(splits, splits[1:], strict=False):
            centre = (x0 + x1) / 2 + (0.8 if y == corridor_high else -0.8)
            plan.hwall(x0, centre - door / 2, y)
            plan.hwall(centre + door / 2, x1, y)
        for x in splits[1:-1]:
            if y == corridor_high:
                plan.vwall(x, corridor_high, height)
            else:
                plan.vwall(x, 0, corridor_low)
    # A doorway between two south rooms, and a meeting-room alcove wall.
    plan.fill(7.0 - WALL / 2, 2.0, 7.0 + WALL / 2, 3.0, 254)
    plan.hwall(15.0, 18.0, 12.0)
    ox, oy = -10.0, -7.5  # world origin at the plan's centre

    def at(x, y):
        return x + ox, y + oy

    boxes = []
    for x0 in (0, 5, 10):  # desks in the north rooms
        boxes.append(((*at(x0 + 2.5, 13.6), 0.0), (1.6, 0.8, 0.75), WOOD))
    boxes += [
        ((*at(3.5, 1.0), 0.0), (2.5, 0.6, 1.8), WOOD),  # bookcases
        ((*at(16.5, 3.0), 0.0), (2.0, 1.0, 0.75), GREY),  # meeting table
        ((*at(10.0, 4.5), 0.3), (0.8, 0.8, 0.8), RED),
        ((*at(19.2, 7.5), 0.0), (0.6, 1.2, 1.0), GREY),  # cabinet at the corridor's end
    ]
    cylinders = [
        (at(12.0, 2.0), 0.3, 1.0, BLUE),
        (at(17.5, 10.5), 0.25, 0.9, GREEN),
        (at(1.0, 10.0), 0.2, 1.2, RED),
    ]
    return World(
        "office",
        plan,
        origin=(ox, oy, 0.0),
        start=(*at(1.5, 7.5), 0.0),
        boxes=boxes,
        cylinders=cylinders,
        comment="office: 20 x 15 m, a long corridor, rooms with doors (good for mapping)",
    )


HAND_MADE = (playground, maze, office)
