"""A building-scale world: family buildings packed side by side on one square floor plan.

    world = campus(100.0)                     # a World named campus_100
    write_world(out_dir, world)               # campus_100.yaml + campus_100.pgm (2000 x 2000)

Buildings of every family (office, hospital, warehouse, ring, lab, in turn, seeds 1, 2, ...)
are laid out in rows, left to right, a street apart, inside an outer wall: a building that
does not fit is skipped, a row ends when none of the next five fits, and the plan is full when
a row holds none. Each keeps its walls, doors and furniture, so the plan holds as many walls per
square metre as the families do (a large world to load and to simulate, not an empty one).
The robot starts at the first building's start. The same size always gives the same bytes.
"""

from bullet_turtlebot import world_families
from bullet_turtlebot.world_file import RESOLUTION, WALL, Plan, World

STREET = 2.0  # m between buildings, and between them and the outer wall


def _paste(plan, building, x0, y0):
    """Copy a building's plan into `plan` with its lower-left corner at (x0, y0) (metres)."""
    c0, r0 = round(x0 / RESOLUTION), round(y0 / RESOLUTION)
    src = building.plan
    for row in range(src.rows):  # row 0 is the top of either image
        dst_row = plan.rows - 1 - (r0 + src.rows - 1 - row)
        start = dst_row * plan.cols + c0
        plan.pixels[start : start + src.cols] = src.pixels[row * src.cols : (row + 1) * src.cols]


def _shifted(building, dx, dy):
    """The building's boxes and cylinders, moved by (dx, dy)."""
    boxes = [
        ((round(x + dx, 3), round(y + dy, 3), yaw), size, colour)
        for (x, y, yaw), size, colour in building.boxes
    ]
    cylinders = [
        ((round(x + dx, 3), round(y + dy, 3)), radius, height, colour)
        for (x, y), radius, height, colour in building.cylinders
    ]
    return boxes, cylinders


def campus(size=100.0, name=None):
    """A size x size m World of family buildings (see the module's docstring)."""
    if not size >= 2 * STREET + world_families.MAX_SIZE:
        raise ValueError(
            f"campus size {size} m is too small: give {2 * STREET + world_families.MAX_SIZE} m "
            "or more (the largest family building plus the streets round it)"
        )
    name = name or f"campus_{size:g}"
    plan = Plan(size, size)
    plan.outline()
    half = size / 2
    boxes, cylinders, start, placed = [], [], None, []
    families = list(world_families.FAMILIES)
    y, index = STREET, 0
    while True:  # rows, bottom to top
        x, row_height, misses = STREET, 0.0, 0
        while misses < len(families):  # left to right; a row ends when no family fits
            family = families[index % len(families)]
            building = world_families.generate(family, index // len(families) + 1)
            index += 1
            width, height = building.size
            if x + width > size - STREET or y + height > size - STREET:
                misses += 1
                continue
            misses = 0
            _paste(plan, building, x, y)
            # A family world is centred on its origin; here its centre is (x + w/2, y + h/2).
            dx, dy = x + width / 2 - half, y + height / 2 - half
            more_boxes, more_cylinders = _shifted(building, dx, dy)
            boxes += more_boxes
            cylinders += more_cylinders
            if start is None:
                sx, sy, syaw = building.start
                start = (round(sx + dx, 3), round(sy + dy, 3), syaw)
            placed.append(building.name)
            x += width + STREET
            row_height = max(row_height, height)
        if row_height == 0.0:
            break
        y += row_height + STREET
    comment = (
        f"{name}: {size:g} x {size:g} m, {len(placed)} family buildings a {STREET:g} m street "
        f"apart ({', '.join(placed)}); outer wall {WALL:g} m"
    )
    return World(
        name,
        plan,
        origin=(-half, -half, 0.0),
        start=start,
        boxes=boxes,
        cylinders=cylinders,
        comment=comment,
        generated_by=f"bullet_turtlebot.campus.campus({size:g})",
    )
