#!/usr/bin/python3
"""Generate worlds (map_server YAML + PGM, plus primitives) deterministically.

    rosrun bullet_turtlebot make_worlds.py [OUTPUT_DIR]
        the shipped worlds: playground, maze, office, and hospital, warehouse, ring, lab (each
        family's seed 1); to regenerate the package's own, give its source folder:
        rosrun bullet_turtlebot make_worlds.py catkin_ws/src/bullet_turtlebot/worlds
    rosrun bullet_turtlebot make_worlds.py --family warehouse --seed 3 [--name N] [OUTPUT_DIR]
        one world of a procedural family: warehouse_3.yaml + .pgm

OUTPUT_DIR defaults to the current folder (never the installed package, which may not be
writable and is not where the shipped worlds are kept).

The same arguments always write the same bytes. A family world is checked before it is
written: the start has room around it and all free space is reachable from it.
"""

import argparse
import sys
from pathlib import Path

from bullet_turtlebot import shipped_worlds, world_families
from bullet_turtlebot.world_file import write_world


def parse_args(argv):
    parser = argparse.ArgumentParser(prog="make_worlds.py", description=__doc__.split("\n")[0])
    parser.add_argument("out_dir", nargs="?", default=".", help="output folder (default: .)")
    parser.add_argument("--family", choices=list(world_families.FAMILIES))
    parser.add_argument("--seed", type=int, default=1, help="the family's seed (default 1)")
    parser.add_argument("--name", help="file name without extension (default FAMILY_SEED)")
    args = parser.parse_args(argv)
    if args.family is None and args.name is not None:
        parser.error("--name needs --family")
    if args.name is not None and (args.name in ("", ".", "..") or "/" in args.name):
        parser.error(f"--name {args.name!r} must be a file name without a folder, e.g. --name big")
    if args.out_dir is not None and Path(args.out_dir).exists() and not Path(args.out_dir).is_dir():
        parser.error(f"{args.out_dir} is a file; give a folder to write the world into")
    return args


def checked(world, out_dir):
    """Write a family world, refusing (exit status 1) one a robot could not explore."""
    from bullet_turtlebot.world_check import load_grid, problems  # numpy and scipy

    path = write_world(out_dir, world)
    found = problems(load_grid(path))
    if found:
        sys.exit(f"make_worlds.py: {path}: " + "; ".join(found))
    return path


def make_folder(out_dir):
    try:
        out_dir.mkdir(parents=True, exist_ok=True)
    except OSError as err:
        sys.exit(f"make_worlds.py: cannot create the folder {out_dir}: {err.strerror or err}")


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    if args.family:
        out_dir = Path(args.out_dir or ".")
        make_folder(out_dir)
        world = world_families.generate(args.family, args.seed, args.name)
        path = checked(world, out_dir)
        print(f"wrote {path} ({world.comment.split(': ', 1)[1]})")
        return
    out_dir = Path(args.out_dir or ".")
    make_folder(out_dir)
    for make in shipped_worlds.HAND_MADE:
        write_world(out_dir, make())
    for family in world_families.SHIPPED:
        checked(world_families.generate(family, 1, name=family), out_dir)
    names = [make.__name__ for make in shipped_worlds.HAND_MADE] + list(world_families.SHIPPED)
    print(f"wrote {', '.join(names)} to {out_dir.resolve()}")


if __name__ == "__main__":
    main()
