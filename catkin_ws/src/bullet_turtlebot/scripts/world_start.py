#!/usr/bin/python3
"""Print one component (x, y or yaw) of a world's start pose, where the simulator puts the
robot: launch files run it from `<param command=...>` to give amcl that pose.

    world_start.py WORLD x|y|yaw [WORLDS_DIR]
"""

import sys
from pathlib import Path

from bullet_turtlebot.world_start import start_pose

COMPONENTS = ("x", "y", "yaw")


def main(argv):
    if len(argv) not in (2, 3) or argv[1] not in COMPONENTS:
        sys.exit("usage: world_start.py WORLD x|y|yaw [WORLDS_DIR]")
    worlds_dir = argv[2] if len(argv) == 3 else Path(__file__).resolve().parent.parent / "worlds"
    try:
        pose = start_pose(argv[0], worlds_dir)
    except ValueError as err:
        sys.exit(f"world_start.py: {err}")
    print(pose[COMPONENTS.index(argv[1])])


if __name__ == "__main__":
    main(sys.argv[1:])
