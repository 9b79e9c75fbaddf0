"""Shared by the slam_gmapping node tests: start the node under sim time with the book's map
bounds, drive the synthetic laser robot (synthetic_scans.py, which is the /clock), and read
the published grid (cells, the synthetic room's walls and free space)."""

import math
from pathlib import Path

from roskit import DEBIAN_PYTHON
from rospkg import RosPack

HERE = Path(__file__).resolve().parent
ROBOT = [DEBIAN_PYTHON, str(HERE / "synthetic_scans.py")]
BOOK_BOUNDS = {"xmin": -10, "xmax": 10, "ymin": -10, "ymax": 10}


def load_turtlebot_tuning(ros):
    """Load the Turtlebot tuning (gmapping_lite's config/turtlebot.yaml, as rospack finds it)
    into slam_gmapping's private namespace, as the launch files do; start_slam's parameters
    then override it."""
    tuning = Path(RosPack().get_path("gmapping_lite")) / "config" / "turtlebot.yaml"
    ros.run(["rosparam", "load", str(tuning), "/slam_gmapping"])


def start_slam(ros, **params):
    ros.run(["rosparam", "set", "/use_sim_time", "true"])
    params.setdefault("base_frame", "base_footprint")
    for name, value in BOOK_BOUNDS.items():  # a 400 x 400 map instead of 4000 x 4000
        params.setdefault(name, value)
    for name, value in params.items():
        ros.run(["rosparam", "set", f"/slam_gmapping/{name}", str(value)])
    node = ros.start(["rosrun", "gmapping_lite", "slam_gmapping"], name="slam_gmapping")
    ros.wait_for_topic("map_metadata")
    return node


def drive(ros, *options, timeout=120):
    robot = ros.start(ROBOT + list(options), name="synthetic_scans")
    robot.wait(timeout=timeout)
    assert robot.returncode == 0, ros.output(robot)


def record_drive(ros, bag, *options):
    """Drive the robot (with `options`) while rosbag records its scans and tf into `bag`."""
    topics = ["/scan", "/tf", "/tf_static"]
    recorder = ros.start(["rosbag", "record", "-O", str(bag), *topics])

    def subscribed():
        subscribers = dict(ros.system_state()[1])
        return all(any("record" in n for n in subscribers.get(t, [])) for t in topics)

    ros.wait_for(subscribed, 60, "rosbag record to subscribe to " + ", ".join(topics))
    drive(ros, *options)
    ros.stop(recorder)
    # rosbag's recording child closes (renames) the bag after the wrapper has exited.
    ros.wait_for(lambda: Path(bag).exists(), 60, "the bag to be closed")


def seconds(stamp):
    """A recorded time (the probe records rospy.Time as {secs, nsecs}) in seconds."""
    return stamp["secs"] + stamp["nsecs"] * 1e-9 if isinstance(stamp, dict) else stamp


def cell(grid, x, y):
    info = grid["info"]
    i = int(math.floor((x - info["origin"]["position"]["x"]) / info["resolution"]))
    j = int(math.floor((y - info["origin"]["position"]["y"]) / info["resolution"]))
    return grid["data"][j * info["width"] + i]


def near(grid, x, y, value, reach=0.1):
    """True if some cell within `reach` of (x, y) holds `value`."""
    steps = [k * 0.05 for k in range(-int(reach / 0.05), int(reach / 0.05) + 1)]
    return any(cell(grid, x + dx, y + dy) == value for dx in steps for dy in steps)


def assert_room_mapped(grid):
    """The synthetic room: walls at x = +-4, y = +-3, a box at (1.5..2.1, 1.0..1.6)."""
    for y in (-2.0, -1.0, 0.5, 2.0):
        assert near(grid, -4.0, y, 100), f"west wall missing at y={y}"
    for x in (-3.0, -1.0, 1.0, 3.0):
        assert near(grid, x, 3.0, 100), f"north wall missing at x={x}"
        assert near(grid, x, -3.0, 100), f"south wall missing at x={x}"
    assert near(grid, 1.5, 1.3, 100), "box missing"
    for x, y in ((0.5, 0.0), (-2.0, -1.5), (-2.5, 2.0), (3.0, -2.0)):
        assert cell(grid, x, y) == 0, f"({x}, {y}) should be free"


def wait_for_room_mapped(ros, node=None, timeout=60):
    """assert_room_mapped on the node's newest map, until it passes or `timeout` s: when the
    drive or the playback ends the node may still be taking in the last scans (it works
    through them at the CPU's pace). Fails with the last check's reason and the node's log."""
    reason = []

    def mapped():
        try:
            assert_room_mapped(ros.echo("map")[0]["msg"])
        except AssertionError as error:
            reason[:] = [str(error)]
            return False
        return True

    try:
        ros.wait_for(mapped, timeout, "the room in the map", interval=1.0)
    except Exception as error:
        log = ros.output(node)[-3000:] if node is not None else ""
        raise AssertionError(f"{reason[-1] if reason else error}\n{log}") from None
