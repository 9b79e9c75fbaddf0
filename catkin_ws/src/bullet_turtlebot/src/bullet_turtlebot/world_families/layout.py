"""What the families share: a floor plan with interior walls, doors and see-through gaps, and
furniture placed by rejection so that it never blocks a door or closes a passage.

Plan coordinates: (0, 0) is the plan's lower-left corner; the world's origin is its centre.
Furniture is either flush against a wall of its room or at least `gap` from every wall, and
always at least `gap` from other furniture, so a robot narrower than the gap passes
everywhere; door approaches and the start are kept clear.
"""

import math
from dataclasses import dataclass

from bullet_turtlebot.world_file import RESOLUTION, WALL, Opening, Plan, World

INNER_WALL = 0.1  # m: two cells, so interior wall faces fall on cell edges
PASSAGE = 0.5  # m: default free gap around furniture (the robot is 0.36 m wide)
DOOR_APPROACH = 0.9  # m kept free of furniture on each side of a door
DOOR_SIDE = 0.2  # m kept free beyond each jamb
GAP_VIEW = 0.6  # m kept free on each side of a see-through gap, so the laser sees through
START_CLEAR = 1.0  # m: half-side of the square kept free around the start
EPS = 1e-6


def snap(value, step=RESOLUTION):
    return round(round(value / step) * step, 3)


def pick(rng, lo, hi, step):
    """A value lo + k * step in [lo, hi]; None when the range is empty."""
    if hi < lo - EPS:
        return None
    return round(lo + step * rng.randint(0, math.floor((hi - lo) / step + EPS)), 3)


@dataclass(frozen=True)
class Rect:
    x0: float
    y0: float
    x1: float
    y1: float

    @staticmethod
    def around(x, y, sx, sy):
        return Rect(x - sx / 2, y - sy / 2, x + sx / 2, y + sy / 2)

    @property
    def width(self):
        return self.x1 - self.x0

    @property
    def height(self):
        return self.y1 - self.y0

    @property
    def centre(self):
        return (self.x0 + self.x1) / 2, (self.y0 + self.y1) / 2

    def grown(self, d):
        return Rect(self.x0 - d, self.y0 - d, self.x1 + d, self.y1 + d)

    def overlaps(self, other):
        return (
            self.x0 < other.x1 - EPS
            and other.x0 < self.x1 - EPS
            and self.y0 < other.y1 - EPS
            and other.y0 < self.y1 - EPS
        )

    def contains(self, other):
        return (
            self.x0 - EPS <= other.x0
            and other.x1 <= self.x1 + EPS
            and self.y0 - EPS <= other.y0
            and other.y1 <= self.y1 + EPS
        )


class Layout:
    """A floor plan being built: walls in a Plan, furniture as footprints."""

    def __init__(self, width, height):
        self.width, self.height = width, height
        self.plan = Plan(width, height)
        self.plan.outline()
        self.boxes = []  # (footprint Rect, height, colour)
        self.cylinders = []  # ((x, y), radius, height, colour)
        self.taken = []  # footprints of everything placed
        self.keep_out = []  # door approaches and the start
        self.doors, self.gaps = [], []
        self.start = None

    def set_start(self, x, y, yaw):
        self.start = (x, y, yaw)
        self.keep_out.append(Rect.around(x, y, 2 * START_CLEAR, 2 * START_CLEAR))

    def interior(self, x0, y0, x1, y1):
        """The free floor of a room given its walls' centre lines (the plan's edges for the
        outer walls)."""

        def inset(v, border):
            return WALL if abs(v - border) < EPS else INNER_WALL / 2

        return Rect(
            x0 + inset(x0, 0),
            y0 + inset(y0, 0),
            x1 - inset(x1, self.width),
            y1 - inset(y1, self.height),
        )

    def wall(self, x0, y0, x1, y1, doors=(), gaps=()):
        """An axis-aligned interior wall along its centre line, overlapping what its ends meet;
        doors and gaps are (centre along the wall, clear width)."""
        along_x = abs(y0 - y1) < EPS
        fixed = y0 if along_x else x0
        a0, a1 = sorted((x0, x1) if along_x else (y0, y1))
        openings = sorted([(c, w, True) for c, w in doors] + [(c, w, False) for c, w in gaps])
        pos = a0 - INNER_WALL / 2
        for centre, width, is_door in openings:
            self._segment(along_x, fixed, pos, centre - width / 2)
            pos = centre + width / 2
            self.opening(along_x, fixed, centre, width, is_door)
        self._segment(along_x, fixed, pos, a1 + INNER_WALL / 2)

    def opening(self, along_x, fixed, centre, width, is_door=True):
        """Record a door or a see-through gap, and keep furniture out of its way."""
        x, y = (centre, fixed) if along_x else (fixed, centre)
        (self.doors if is_door else self.gaps).append(Opening(x, y, width, along_x))
        across = 2 * (DOOR_APPROACH if is_door else GAP_VIEW)
        along = width + 2 * DOOR_SIDE
        self.keep_out.append(Rect.around(x, y, *((along, across) if along_x else (across, along))))

    def _segment(self, along_x, fixed, a, b):
        if b - a < EPS:
            return
        half = INNER_WALL / 2
        if along_x:
            self.plan.fill(a, fixed - half, b, fixed + half)
        else:
            self.plan.fill(fixed - half, a, fixed + half, b)

    def solid(self, rect, free=False):
        """Fill a block of wall (or, with free, carve free floor out of one)."""
        self.plan.fill(rect.x0, rect.y0, rect.x1, rect.y1, 254 if free else 0)

    def fits(self, footprint, room, gap):
        if not room.contains(footprint):
            return False
        faces = (
            footprint.x0 - room.x0,
            room.x1 - footprint.x1,
            footprint.y0 - room.y0,
            room.y1 - footprint.y1,
        )
        if any(EPS < d < gap - EPS for d in faces):
            return False  # neither flush nor leaving a passage
        if faces[0] + faces[1] < gap - EPS or faces[2] + faces[3] < gap - EPS:
            return False  # wall to wall: it would cut the room in two
        if any(footprint.overlaps(k) for k in self.keep_out):
            return False
        return not any(footprint.grown(gap).overlaps(t) for t in self.taken)

    def add_box(self, footprint, height, colour):
        self.taken.append(footprint)
        self.boxes.append((footprint, height, colour))

    def add_cylinder(self, x, y, radius, height, colour):
        self.taken.append(Rect.around(x, y, 2 * radius, 2 * radius))
        self.cylinders.append(((x, y), radius, height, colour))

    def place_box(self, rng, room, size, height, colour, flush=True, gap=PASSAGE, tries=40):
        """A box of size (length, depth) in room, its long side against a wall if flush;
        returns its footprint, or None if no spot was found."""
        for _ in range(tries):
            footprint = self._spot(rng, room, *size, flush)
            if footprint and self.fits(footprint, room, gap):
                self.add_box(footprint, height, colour)
                return footprint
        return None

    def place_cylinder(self, rng, room, radius, height, colour, flush=True, gap=PASSAGE):
        for _ in range(40):
            footprint = self._spot(rng, room, 2 * radius, 2 * radius, flush)
            if footprint and self.fits(footprint, room, gap):
                self.add_cylinder(*footprint.centre, radius, height, colour)
                return footprint
        return None

    def _spot(self, rng, room, length, depth, flush):
        if not flush:
            sx, sy = (length, depth) if rng.random() < 0.5 else (depth, length)
            x = pick(rng, room.x0 + sx / 2, room.x1 - sx / 2, RESOLUTION)
            y = pick(rng, room.y0 + sy / 2, room.y1 - sy / 2, RESOLUTION)
            return None if x is None or y is None else Rect.around(x, y, sx, sy)
        side = rng.randrange(4)  # south, north, west, east
        if side < 2:
            x = self._along(rng, room.x0, room.x1, length)
            y = room.y0 + depth / 2 if side == 0 else room.y1 - depth / 2
            return None if x is None else Rect.around(x, y, length, depth)
        y = self._along(rng, room.y0, room.y1, length)
        x = room.x0 + depth / 2 if side == 2 else room.x1 - depth / 2
        return None if y is None else Rect.around(x, y, depth, length)

    @staticmethod
    def _along(rng, lo, hi, length):
        """A centre along a wall: in either corner now and then, else anywhere."""
        if hi - lo < length:
            return None
        corner = rng.random()
        if corner < 0.2:
            return lo + length / 2
        if corner < 0.4:
            return hi - length / 2
        return pick(rng, lo + length / 2, hi - length / 2, RESOLUTION)

    def world(self, name, comment, generated_by):
        """The finished World, centred on the world origin."""
        ox, oy = -self.width / 2, -self.height / 2

        def at(x, y):
            return round(x + ox, 3), round(y + oy, 3)

        def shifted(opening):
            return Opening(*at(opening.x, opening.y), opening.width, opening.along_x)

        boxes = [
            ((*at(*f.centre), 0.0), (round(f.width, 3), round(f.height, 3), h), colour)
            for f, h, colour in self.boxes
        ]
        cylinders = [(at(x, y), r, h, colour) for (x, y), r, h, colour in self.cylinders]
        return World(
            name,
            self.plan,
            origin=(ox, oy, 0.0),
            start=(*at(*self.start[:2]), self.start[2]),
            boxes=boxes,
            cylinders=cylinders,
            comment=comment,
            generated_by=generated_by,
            doors=[shifted(d) for d in self.doors],
            gaps=[shifted(g) for g in self.gaps],
        )


def split(rng, start, end, narrowest, widest, step=0.5):
    """Cut [start, end] into spans of narrowest..widest (widest >= 2 * narrowest)."""
    cuts = [start]
    while end - cuts[-1] > widest + EPS:
        span = pick(rng, narrowest, min(widest, end - cuts[-1] - narrowest), step)
        cuts.append(round(cuts[-1] + span, 3))
    return cuts + [end]


def free_centre(rng, lo, hi, width, taken, spacing, tries=30):
    """A centre for an opening of width within [lo, hi], keeping spacing from the
    (centre, width) openings already in taken; None if none fits."""
    first = math.ceil(lo / RESOLUTION - EPS) * RESOLUTION  # jambs on cell edges
    for _ in range(tries):
        jamb = pick(rng, first, hi - width, RESOLUTION)
        if jamb is None:
            return None
        centre = round(jamb + width / 2, 3)
        if all(abs(centre - c) >= (width + w) / 2 + spacing - EPS for c, w in taken):
            return centre
    return None
