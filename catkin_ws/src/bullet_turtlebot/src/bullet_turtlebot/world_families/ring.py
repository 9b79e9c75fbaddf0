"""ring: a loop corridor around a solid central block (circuit >= 40 m along its centre
line) that SLAM must close. Each side has its own width; a few rooms open off the block and
cabinets and bins stand against the walls."""

from bullet_turtlebot.world_families.layout import INNER_WALL, Layout, Rect, pick, snap
from bullet_turtlebot.world_file import BLUE, GREEN, GREY, WALL, WOOD

SIZE = ((16.0, 24.0), (11.0, 16.0))  # width, height ranges (m)
CORRIDOR = (1.6, 2.6)  # m between the outer wall and the block (centre lines)
MIN_CIRCUIT = 40.0
PASS = 0.9  # m of corridor kept free beside anything standing in it


def build(rng):
    width, height = pick(rng, 16.0, 24.0, 0.5), pick(rng, 11.0, 16.0, 0.5)
    west, east, south, north = (pick(rng, *CORRIDOR, 0.1) for _ in range(4))
    layout = Layout(width, height)
    block = Rect(west, south, round(width - east, 3), round(height - north, 3))
    layout.solid(block)
    layout.set_start(snap(width / 2), snap((WALL + south) / 2), 0.0)
    rooms = add_rooms(rng, layout, block)
    # One strip per side, without the corners: a strip's ends are open corridor, not walls.
    corridors = (
        Rect(block.x0, WALL, block.x1, block.y0),
        Rect(block.x0, block.y1, block.x1, height - WALL),
        Rect(WALL, block.y0, block.x0, block.y1),
        Rect(block.x1, block.y0, width - WALL, block.y1),
    )
    for _ in range(rng.randint(4, 8)):
        strip = rng.choice(corridors)
        size = (pick(rng, 0.8, 2.0, 0.2), pick(rng, 0.4, 0.6, 0.1))
        colour = rng.choice((WOOD, GREY))
        layout.place_box(rng, strip, size, pick(rng, 0.8, 1.8, 0.2), colour, gap=PASS)
    for _ in range(rng.randint(2, 4)):
        strip = rng.choice(corridors)
        layout.place_cylinder(rng, strip, pick(rng, 0.2, 0.3, 0.05), 0.9, GREEN, gap=PASS)
    circuit = 2 * ((width - (west + east) / 2) + (height - (south + north) / 2))
    assert circuit >= MIN_CIRCUIT, circuit  # holds for every size and corridor in range
    block_size = f"{block.width:g} x {block.height:g} m"
    return layout, f"a {circuit:.1f} m loop around a {block_size} block, {rooms} rooms"


def add_rooms(rng, layout, block):
    """Rooms carved into the block from its south and north faces, each with one door."""
    count = 0
    deepest = (block.height - 1.0) / 2  # rooms from both faces never meet
    for face_y, inward in ((block.y0, 1), (block.y1, -1)):
        if rng.random() < 0.3:
            continue
        room_width = pick(rng, 2.5, 4.0, 0.5)
        depth = pick(rng, 2.0, min(3.0, deepest), 0.5)
        x0 = pick(rng, block.x0 + 1.0, block.x1 - 1.0 - room_width, 0.5)
        if depth is None or x0 is None:
            continue
        near, far = face_y + inward * INNER_WALL, face_y + inward * (depth - INNER_WALL)
        inside = Rect(x0 + INNER_WALL, min(near, far), x0 + room_width - INNER_WALL, max(near, far))
        layout.solid(inside, free=True)
        door = pick(rng, 0.9, 1.2, 0.1)
        centre = snap(x0 + room_width / 2)
        cut = Rect.around(centre, face_y + inward * INNER_WALL / 2, door, 2 * INNER_WALL)
        layout.solid(cut, free=True)
        layout.opening(True, face_y + inward * INNER_WALL / 2, centre, door)
        layout.place_box(rng, inside, (pick(rng, 0.8, 1.6, 0.2), 0.5), 1.0, BLUE)
        count += 1
    return count
