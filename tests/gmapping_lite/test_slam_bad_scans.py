"""slam_gmapping (gmapping_lite) fed scans whose layout no laser can have: each is dropped
with a throttled warning naming the reason and the running count, the node keeps running,
and the good scans that follow still build the map; slam_offline likewise over a bag. Also a
laser reporting a huge range_max ("no limit"): the default maxRange is clamped to 80 m, said
once, and the map is sane."""

import re
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
from slam_node_kit import (  # noqa: E402
    BOOK_BOUNDS,
    assert_room_mapped,
    drive,
    record_drive,
    seconds,
    start_slam,
)

MALFORMED_UNTIL = 6.0  # sim seconds after the robot's start (100 s) of malformed scans
SCAN_PERIOD = 0.1  # synthetic_scans.py: 10 Hz scans
DROPPED = re.compile(
    r"dropping a malformed scan on frame 'base_laser' at ([\d.]+): (.*); "
    r"malformed scans dropped so far: (\d+)"
)
# What scanProblem says about each of synthetic_scans.py's malformations.
REASONS = {
    "zero-increment": "angle_increment is 0: it must be a finite, non-zero angle between beams",
    "short": "180 ranges, but angle_min -2 to angle_max 2 in steps of angle_increment",
    "range-order": "range_min 8 is not below range_max 0.1",
}


@pytest.mark.parametrize("kind", sorted(REASONS))
def test_malformed_scans_are_dropped_counted_and_named(ros, kind):
    node = start_slam(ros, map_update_interval=1.0)
    drive(ros, "--malformed", kind, "--malformed-until", str(MALFORMED_UNTIL))
    assert node.poll() is None, "slam_gmapping exited:\n" + ros.output(node)[-3000:]
    log = ros.output(node)
    drops = [(float(t), reason, int(n)) for t, reason, n in DROPPED.findall(log)]
    assert drops, log[-3000:]
    # The first drop is reported at once, with its reason and the count.
    assert drops[0][0] == pytest.approx(100.0)
    assert drops[0][2] == 1
    assert all(REASONS[kind] in reason for _, reason, _ in drops), drops
    # Throttled to one line per 5 s of scan time: 6 s of bad scans from 100.0 give a second
    # line at 105.0, counting on (51, fewer if the node's queue overflowed), and no more.
    assert len(drops) == 2, drops
    t, _, n = drops[1]
    assert 105.0 <= t < 100.0 + MALFORMED_UNTIL, drops
    assert 1 < n <= round((t - 100.0) / SCAN_PERIOD) + 1, drops
    # The good scans afterwards build the map: the latched map is stamped after the bad ones.
    grid = ros.echo("map")[0]["msg"]
    assert seconds(grid["header"]["stamp"]) >= 100.0 + MALFORMED_UNTIL
    assert_room_mapped(grid)
    assert "update 0 (scan" in log


def test_slam_offline_drops_malformed_scans_from_a_bag(ros, tmp_path):
    bag = tmp_path / "data.bag"
    record_drive(ros, bag, "--duration", "26", "--malformed", "short")
    cmd = ["rosrun", "gmapping_lite", "slam_offline", str(bag), "--out", str(tmp_path / "map")]
    cmd += ["--base-frame", "base_footprint"]
    for name, value in BOOK_BOUNDS.items():
        cmd += ["--param", f"{name}={value}"]
    done = ros.run(cmd, timeout=120)
    # Throttled by bag time: 3 s of malformed scans give one line, the first.
    drops = DROPPED.findall(done.stderr)
    assert len(drops) == 1, done.stderr
    assert float(drops[0][0]) == pytest.approx(100.0)
    assert REASONS["short"] in drops[0][1] and drops[0][2] == "1", drops
    # The summary counts them all (30 scans in the first 3 s, less any the recorder missed).
    # Every good scan finds its odometry, though the recorder's clock (wall time, the robot
    # runs at 4x) spans a quarter of the stamps' 26 s.
    summary = re.search(r"(\d+) scans \(0 without odometry, (\d+) malformed\)", done.stdout)
    assert summary, done.stdout + done.stderr
    assert 0 < int(summary[2]) <= 30 and int(summary[1]) > 200, summary[0]
    assert (tmp_path / "map.pgm").exists() and (tmp_path / "map.yaml").exists()
    # The odometry period the motion prior used, measured from the bag: synthetic_scans.py
    # publishes odom -> base_footprint every 50 Hz tick.
    assert "odometry every 0.020 s (measured)" in done.stdout, done.stdout


def test_huge_range_max_is_clamped_once_for_the_default_max_range(ros):
    node = start_slam(ros, map_update_interval=1.0)
    # No east wall: those beams read "no return" and clear space out to maxUrange.
    drive(ros, "--range-max", "1e30", "--open-wall")
    assert node.poll() is None, "slam_gmapping exited:\n" + ros.output(node)[-3000:]
    log = ros.output(node)
    note = "the scan's range_max 1e+30 is beyond 80 m; using maxRange 80 m"
    assert log.count(note) == 1, log[-3000:]
    assert "maxRange 79.99 m, maxUrange 79.99 m" in log
    # The map grew east as far as the clamped range (from x <= 2.1 m), not towards 1e30.
    meta = ros.echo("map_metadata")[0]["msg"]
    east_edge = meta["origin"]["position"]["x"] + meta["width"] * meta["resolution"]
    assert 80.0 < east_edge < 2.1 + 80.0 + 2.0, meta
