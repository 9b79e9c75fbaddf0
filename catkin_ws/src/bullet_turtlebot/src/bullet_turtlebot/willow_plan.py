"""The Willow Garage floor plan (Stage's `willow-full.pgm`) as a simulator world file.

The image is not shipped: it is read in place (beside the checkout, ../shared/data/), so a
world file for it is written on the fly, naming the image by its absolute path.
"""

from pathlib import Path

# Stage's willow example draws the 540 x 587 image at 54.0 m x 58.7 m.
RESOLUTION = 0.1
# A free spot near the plan's middle, where bench_simulator has always started.
CENTRE_START = (27.0, 29.0, 0.0)


def world_text(image, start=CENTRE_START, comment=None):
    """The world YAML for the plan at `image`, the robot starting at `start` (x, y, yaw)."""
    x, y, yaw = (float(v) for v in start)
    head = "".join(f"# {line}\n" for line in comment.splitlines()) if comment else ""
    return (
        f"{head}image: {Path(image).resolve()}\nresolution: {RESOLUTION}\n"
        "origin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n"
        f"start: [{x!r}, {y!r}, {yaw!r}]\n"
    )


def write_world(path, image, start=CENTRE_START, comment=None):
    """Write the world file to `path`; returns the path, or None when `image` is absent."""
    if not Path(image).is_file():
        return None
    path = Path(path)
    path.write_text(world_text(image, start, comment))
    return path
