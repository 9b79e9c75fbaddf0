"""The run's bag in --out: recorded under a name of its own and moved over the bag of an
earlier run only once this run completed, so a run stopped half-way (Ctrl-C, a node that
died, a failed map_saver) leaves the previous complete bag in place."""

import os
from pathlib import Path


def partial_bag(bag):
    """Where the run records: NAME.partial.bag beside NAME.bag (rosbag adds .active while
    it writes). Same folder, so the final move is an atomic rename."""
    bag = Path(bag)
    return bag.with_name(f"{bag.stem}.partial.bag")


def finish_bag(bag, completed):
    """After the recorder stopped: move the run's bag into place when the run `completed`.
    Returns None when the bag is in place, else a line for the user saying what was kept."""
    bag, partial = Path(bag), partial_bag(bag)
    active = partial.with_name(partial.name + ".active")
    recorded = partial if partial.exists() else active if active.exists() else None
    if completed and recorded is partial:
        os.replace(partial, bag)
        return None
    if completed:  # rosbag was killed before it could close (and index) the file
        why = "its recording was not closed"
    else:
        why = "the run did not finish"
    kept = (
        f"{bag.name} from an earlier run is kept" if bag.exists() else f"no {bag.name} was written"
    )
    left = f"; this run's incomplete recording is {recorded.name}" if recorded else ""
    return f"{why}: {kept}{left}"
