"""warehouse: a big hall, rows of racks with aisles on one side, open floor with a grid of
pillars and a few pallets on the other: long stretches with few features nearby."""

from bullet_turtlebot.world_families.layout import Layout, Rect, pick, snap
from bullet_turtlebot.world_file import GREY, WOOD

SIZE = ((32.0, 45.0), (22.0, 32.0))  # width, height ranges (m)
RACK = (0.3, 0.45, 0.65)
ORANGE = (0.85, 0.5, 0.15)
WALL_CLEAR = 2.5  # m between the racks and the walls
PILLAR_CLEAR = 1.5  # m between a pillar and anything else
PILLAR_WALL_CLEAR = 3.0  # m between a pillar and the walls or racks


def build(rng):
    width, height = pick(rng, 32.0, 45.0, 1.0), pick(rng, 22.0, 32.0, 1.0)
    layout = Layout(width, height)
    layout.set_start(width - 4.0, snap(height / 2), 0.0)
    hall = layout.interior(0.0, 0.0, width, height)
    rows, racks_end = add_racks(rng, layout, width, height)
    pillars = add_pillars(rng, layout, hall, racks_end)
    for _ in range(rng.randint(2, 5)):  # pallet stacks along the walls, above the laser
        layout.place_box(rng, hall, (1.2, 1.0), pick(rng, 0.6, 1.5, 0.3), WOOD, gap=1.0)
    return layout, f"rack rows: {rows}, pillars: {pillars}"


def add_racks(rng, layout, width, height):
    """Rows of racks along x in the west part of the hall; returns (rows, east end)."""
    x0 = pick(rng, WALL_CLEAR, 4.0, 0.5)
    length = snap(pick(rng, 0.25 * width, 0.4 * width, 0.5))
    cross = pick(rng, 2.5, 3.5, 0.5) if length > 12 else 0.0  # a cross aisle halfway
    aisle = pick(rng, 1.8, 3.0, 0.1)
    depth = round(pick(rng, 1.0, 1.2, 0.1) * rng.choice((1, 2)), 3)  # single or back to back
    rack_height = pick(rng, 2.0, 3.0, 0.5)
    if cross:
        half = snap((length - cross) / 2)
        spans = ((x0, x0 + half), (x0 + length - half, x0 + length))
    else:
        spans = ((x0, x0 + length),)
    y, rows = pick(rng, WALL_CLEAR, 4.0, 0.5), 0
    while y + depth <= height - WALL_CLEAR:
        for a, b in spans:
            layout.add_box(Rect(a, y, b, round(y + depth, 3)), rack_height, RACK)
        y, rows = round(y + depth + aisle, 3), rows + 1
    return rows, x0 + length


def add_pillars(rng, layout, hall, west):
    """A regular grid of pillars (round or square) over the open floor east of west."""
    spacing = pick(rng, 8.0, 11.0, 0.5)
    round_pillars = rng.random() < 0.5
    size = pick(rng, 0.4, 0.6, 0.1)
    floor = Rect(west, hall.y0, hall.x1, hall.y1).grown(-PILLAR_WALL_CLEAR)
    count = 0
    for x in grid_line(floor.x0, floor.x1, spacing):
        for y in grid_line(floor.y0, floor.y1, spacing):
            footprint = Rect.around(x, y, size, size)
            if not layout.fits(footprint, hall, PILLAR_CLEAR):
                continue
            if round_pillars:
                layout.add_cylinder(x, y, size / 2, 3.0, GREY)
            else:
                layout.add_box(footprint, 3.0, ORANGE)
            count += 1
    return count


def grid_line(lo, hi, spacing):
    """The centres of the cells, spacing or longer, that [lo, hi] divides into."""
    if hi <= lo:
        return []
    count = max(1, int((hi - lo) // spacing))
    step = (hi - lo) / count
    return [snap(lo + (i + 0.5) * step) for i in range(count)]
