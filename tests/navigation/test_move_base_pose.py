"""move_base_lite's own pose takes a new map -> odom correction when it is published, even
though amcl dates each correction transform_tolerance ahead (1 s in the Turtlebot's
amcl.launch). A plain tf lookup of map -> base_footprint at the latest time interpolates
between corrections published that long ago, so a converging amcl's older error steered the
robot (it stopped ~0.05 rad short of goal headings). No simulator: a map, a goal far off to
keep move_base active, and a helper that publishes the transforms amcl would."""

from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
OFFICE = REPO / "maps" / "office.yaml"
PYTHON = "/usr/bin/python3"
START_X = -8.5  # the office's start, facing along the corridor
AHEAD = 5.0  # s: how far ahead the helper dates each correction
SHIFT = 0.5  # m: the correction's change at the switch (dated_correction.py)


def test_feedback_pose_takes_the_newest_correction_at_once(ros):
    ros.start(["rosrun", "map_server", "map_server", str(OFFICE)], name="map_server")
    ros.start(
        [PYTHON, str(HERE / "dated_correction.py"), "--x", str(START_X), "--ahead", str(AHEAD)],
        name="dated_correction",
    )
    ros.start(["roslaunch", "move_base_lite", "move_base.launch"], name="move_base")
    ros.wait_for_topic("/move_base/status", timeout=90)
    feedback = ros.probe(
        ["/move_base/feedback"],
        ready=False,
        types={"/move_base/feedback": "move_base_msgs/MoveBaseActionFeedback"},
        timeout=300,
    )
    goal = "{header: {frame_id: map}, pose: {position: {x: 5.0, y: 0.0}, orientation: {w: 1.0}}}"
    ros.start(["rostopic", "pub", "/move_base_simple/goal", "geometry_msgs/PoseStamped", goal])

    def poses():
        for m in feedback.messages():
            p = m["msg"]["feedback"]["base_position"]
            yield p["header"]["stamp"], p["pose"]  # the probe gives stamps in seconds

    # The goal is active (feedback comes) before the correction changes.
    ros.wait_for(lambda: any(True for _ in poses()), 120, "move_base's feedback")
    ros.start(["rostopic", "pub", "-1", "/switch_correction", "std_msgs/Empty"])
    switch = ros.echo("/correction_switched", count=1, timeout=120)[0]["msg"]["data"]

    def moved(pose):
        return abs(pose["position"]["x"] - (START_X + SHIFT)) < 0.01

    ros.wait_for(
        lambda: any(t >= switch and moved(p) for t, p in poses()),
        120,
        "move_base's feedback to show the new correction",
    )
    before = [(t, p["position"]["x"]) for t, p in poses() if t < switch]
    first = min(t for t, p in poses() if t >= switch and moved(p))
    assert before and all(abs(x - START_X) < 0.01 for _, x in before), before[-5:]
    # The helper's switch is announced after the new correction is sent; move_base has it
    # within its tf delivery. Before the fix the pose changed only AHEAD seconds later.
    assert first - switch < AHEAD / 2, (switch, first)
