"""Procedural world families, each randomised by a seed: the same family and seed always
give the same World (and so the same file bytes).

    world = generate("warehouse", 3)          # a World named warehouse_3
    write_world(out_dir, world)               # warehouse_3.yaml + warehouse_3.pgm
"""

import random

from bullet_turtlebot.world_families import hospital, lab, office, ring, warehouse

FAMILIES = {
    "office": office,
    "hospital": hospital,
    "warehouse": warehouse,
    "ring": ring,
    "lab": lab,
}
SHIPPED = ("hospital", "warehouse", "ring", "lab")  # shipped as worlds/<family>.yaml, seed 1
MAX_SIZE = 60.0  # m, either side


def size_range(family):
    """((min width, max width), (min height, max height)) in metres."""
    return FAMILIES[family].SIZE


def generate(family, seed, name=None):
    """The World of this family and seed, named name (default FAMILY_SEED)."""
    if family not in FAMILIES:
        raise ValueError(f"unknown world family '{family}' (known: {', '.join(FAMILIES)})")
    rng = random.Random(f"{family}:{seed}")  # str seeds hash the same in every process
    layout, what = FAMILIES[family].build(rng)
    command = f"scripts/make_worlds.py --family {family} --seed {seed}"
    if name:
        command += f" --name {name}"
    name = name or f"{family}_{seed}"
    width, height = layout.width, layout.height
    comment = f"{name}: family {family}, seed {seed}; {width:g} x {height:g} m, {what}"
    return layout.world(name, comment, command)
