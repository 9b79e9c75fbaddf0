"""The Willow Garage floor plan (Stage's `willow-full.pgm`) as a simulator world file.

The image is not shipped: it is read in place (beside the checkout, ../shared/data/), so a
world file for it is written on the fly, naming the image by its absolute path.
"""

from pathlib import Path

# Stage's willow example draws the 540 x 587 image at 54.0 m x 58.7 m.
RESOLUTION = 0.1
# A free spot near the plan's middle, where bench_simulator has always started.
CENTRE_START = (27.0, 29.0, 0.0)
# The plan is itself a map made by a robot: its grey pixels (205, occupancy 50/255 = 0.196,
# map_saver's unknown) are space that robot never saw: courtyards, closed rooms, outdoors.
# map_server's thresholds make them unknown, which the simulator turns into open floor;
# an occupied_thresh just below 0.196 makes them walls instead, so a robot stays indoors.
THRESHOLDS = {False: (0.65, 0.196), True: (0.19, 0.1)}


def world_text(image, start=CENTRE_START, comment=None, unknown_is_wall=False):
    """The world YAML for the plan at `image`, the robot starting at `start` (x, y, yaw);
    the plan's unknown (grey) pixels are open floor, or walls with `unknown_is_wall`."""
    x, y, yaw = (float(v) for v in start)
    occupied, free = THRESHOLDS[bool(unknown_is_wall)]
    head = "".join(f"# {line}\n" for line in comment.splitlines()) if comment else ""
    return (
        f"{head}image: {Path(image).resolve()}\nresolution: {RESOLUTION}\n"
        f"origin: [0, 0, 0]\nnegate: 0\noccupied_thresh: {occupied}\nfree_thresh: {free}\n"
        f"start: [{x!r}, {y!r}, {yaw!r}]\n"
    )


def write_world(path, image, start=CENTRE_START, comment=None, unknown_is_wall=False):
    """Write the world file to `path`; returns the path, or None when `image` is absent."""
    if not Path(image).is_file():
        return None
    path = Path(path)
    path.write_text(world_text(image, start, comment, unknown_is_wall))
    return path
