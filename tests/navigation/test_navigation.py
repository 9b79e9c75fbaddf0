"""Chapter 10 end to end: the simulator in the maze, map_server with the maze's map,
amcl_lite and move_base_lite (amcl_demo.launch), faster than real time. amcl starts from an
rviz-style initial pose that is off; goals are sent through the move_base action and
checked against the simulator's ground truth. Figures are printed."""

import json
import signal
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
REPO = HERE.parent.parent
PYTHON = "/usr/bin/python3"
# The simulator waits for move_base if it lags (wait_for_commands), so results per sim
# second do not depend on the machine's load.
SPEED = 4
START = (0.75, 0.75, 0.0)  # the maze world's start
# Corridor cells of the maze's 1.5 m grid: a straight leg, a leg round a corner, and back.
GOALS = [(3.75, 0.75, 1.5708), (2.25, 2.25, 3.1416), (0.75, 0.75, 0.0)]
# Limits: move_base_lite's goal tolerance is 0.05 m / 0.10 rad; amcl's estimate adds its
# error. Facing a flat wall, the Kinect's 58 degree view cannot tell where along the wall
# the robot is, so at some goals the estimate is off by up to about 0.15 m along it.
GOAL_POSITION_LIMIT = 0.2
XY_GOAL_TOLERANCE = 0.05  # move_base_lite's config/move_base_params.yaml
# m: amcl updates every update_min_d = 0.25 m of travel (amcl.launch); at the simulator's
# odometry noise (a few per cent) and with a last command's worth of slow approach, a few
# centimetres.
DRIFT_SINCE_LAST_UPDATE = 0.05
# rad: move_base_lite's yaw_goal_tolerance (0.10, on its own pose: amcl's estimate) plus amcl's
# heading error once converged (0.10). Measured at the second and third goals of 20 loaded runs
# (session 18): move_base's own pose 0.06-0.10 rad off (it stops on entering the tolerance),
# amcl's heading error at its last update 0.00-0.11, the truth 0.07-0.17 off. Before move_base
# took amcl's newest correction (it used the one amcl made transform_tolerance = 1 s before,
# test_move_base_pose.py), 8 runs gave 0.07-0.18, and one CI run 0.209.
YAW_GOAL_TOLERANCE = 0.10
GOAL_YAW_LIMIT = YAW_GOAL_TOLERANCE + 0.10
# The rviz-style initial pose below is this far off in heading; until amcl has converged (the
# first goal absorbs the offset) its heading error is bounded by it, not by the converged 0.10.
INITIAL_YAW_OFFSET = 0.2
FIRST_GOAL_YAW_LIMIT = YAW_GOAL_TOLERANCE + INITIAL_YAW_OFFSET
AMCL_TRACKING_LIMIT = 0.2  # m, largest error after the first two updates while driving


def start_navigation(ros, package="rosbook_demo", launch_file="amcl_demo.launch", *args):
    ros.start(
        [
            "roslaunch",
            package,
            launch_file,
            "rviz:=false",
            f"speed:={SPEED}",
            "wait_for_commands:=0.3",
            *args,
        ],
        name=launch_file,
    )
    ros.wait_for_topic("amcl_pose", timeout=90)
    ros.wait_for_service("move_base/make_plan", timeout=90)


def run_client(ros, tmp_path, *args, timeout=240):
    out = tmp_path / "nav.jsonl"
    client = ros.start([PYTHON, str(HERE / "nav_client.py"), "--out", str(out), *args])
    ros.wait_for(
        lambda: client.poll() is not None or (out.exists() and '"done"' in out.read_text()),
        timeout,
        "the navigation client to finish",
        interval=0.5,
    )
    assert client.wait(10) == 0, ros.output(client)[-3000:]
    return [json.loads(line) for line in out.read_text().splitlines()]


def goal_args(goals):
    return [a for g in goals for a in ("--goal", ",".join(map(str, g)))]


@pytest.mark.timeout(300)
def test_amcl_converges_from_an_offset_pose_and_goals_are_reached(ros, tmp_path):
    start_navigation(ros)
    # An rviz 2D Pose Estimate 0.3 m and 0.2 rad off the true start.
    offset = f"{START[0] + 0.2},{START[1] - 0.22},{START[2] + INITIAL_YAW_OFFSET}"
    records = run_client(ros, tmp_path, "--initial-pose", offset, *goal_args(GOALS))
    goals = [r for r in records if "goal" in r]
    for r in goals:
        print(
            f"goal {r['goal']}: {r['state']} in {r['sim_seconds']:.1f} sim s, position error "
            f"{r['position_error']:.3f} m, yaw error {r['yaw_error']:.3f} rad, amcl error max "
            f"{r['amcl_max_error']:.3f} m, last {r['amcl_last_error']:.3f} m; move_base's own "
            f"pose {r['own_position_error']:.3f} m, {r['own_yaw_error']:.3f} rad off; amcl heading "
            f"error max {r['amcl_max_yaw_error']:.3f}, last {r['amcl_last_yaw_error']:.3f} rad "
            f"(its sd {r['amcl_last_yaw_sd']:.3f})"
        )
    assert len(goals) == len(GOALS)
    for n, r in enumerate(goals):
        assert r["state"] == "SUCCEEDED", r
        assert r["position_error"] <= GOAL_POSITION_LIMIT, r
        assert r["yaw_error"] <= (FIRST_GOAL_YAW_LIMIT if n == 0 else GOAL_YAW_LIMIT), r
    # Converged: from the second goal on (the first absorbs the initial offset).
    for r in goals[1:]:
        assert r["amcl_max_error"] <= AMCL_TRACKING_LIMIT, r


@pytest.mark.timeout(240)
def test_move_base_interface_plans_costmaps_preemption_and_aborts(ros, tmp_path):
    start_navigation(ros)
    # ~make_plan: a path round the maze's walls, from the start to the first goal.
    plan = ros.run(
        [
            "rosservice",
            "call",
            "/move_base/make_plan",
            "{start: {header: {frame_id: map}, pose: {position: {x: 0.75, y: 0.75}, "
            "orientation: {w: 1}}}, goal: {header: {frame_id: map}, pose: {position: "
            "{x: 2.25, y: 2.25}, orientation: {w: 1}}}, tolerance: 0.0}",
        ],
        timeout=60,
    ).stdout
    assert plan.count("position:") > 20, plan[:2000]
    # The global costmap: the maze's map, inflated.
    costmap = ros.echo("/move_base/global_costmap/costmap", count=1, timeout=60)[0]["msg"]
    assert costmap["header"]["frame_id"] == "map"
    assert costmap["info"]["width"] > 0 and 100 in costmap["data"]
    ros.wait_for_topic("/move_base/local_costmap/costmap")
    # A new goal preempts the current one; then goals that cannot be reached abort: inside
    # the maze's outer wall (x = 0), and off the map.
    records = run_client(
        ros,
        tmp_path,
        "--preempt-after",
        "2",
        *goal_args([(9.75, 9.75, 0.0), (2.25, 2.25, 3.1416), (0.02, 3.0, 0.0), (30.0, 30.0, 0.0)]),
    )
    goals = [r for r in records if "goal" in r]
    print([(r["state"], r["text"], round(r["sim_seconds"], 1)) for r in goals])
    assert records[0]["preempted_goal_state_before"] == "ACTIVE"
    assert goals[0]["state"] == "SUCCEEDED", goals[0]
    # Reached in amcl's map: within the goal tolerance of the goal there, so the true error
    # is at most the tolerance plus amcl's error on the way, plus what odometry drifts and the
    # last command carries the robot after amcl's last update (this test is about the
    # interface; the accuracy test above holds the 0.2 m).
    reached = XY_GOAL_TOLERANCE + goals[0]["amcl_max_error"] + DRIFT_SINCE_LAST_UPDATE
    assert goals[0]["position_error"] <= reached, goals[0]
    assert [r["state"] for r in goals[1:]] == ["ABORTED", "ABORTED"]
    assert "obstacle" in goals[1]["text"]
    assert "outside the map" in goals[2]["text"]


@pytest.mark.timeout(300)
def test_patrol_completes_one_loop_in_turtlebot_in_stage(ros, tmp_path):
    # The book's chapter 10 commands: turtlebot_in_stage.launch (navigation on by default),
    # then patrol.py.
    start_navigation(ros, "turtlebot_stage", "turtlebot_in_stage.launch")
    patrol = ros.start(
        [
            "rosrun",
            "patrolbot",
            "patrol.py",
            "--waypoints",
            str(REPO / "catkin_ws/src/patrolbot/config/maze_waypoints.yaml"),
            "--loops",
            "1",
        ],
        name="patrol",
    )
    ros.wait_for(lambda: patrol.poll() is not None, 240, "patrol.py to finish a loop", 0.5)
    log = ros.output(patrol)
    print(log[-2000:])
    assert patrol.returncode == 0, log
    assert log.count("patrol: reached") == 3, log
    assert "loop 1 done" in log

    # Patrolling for ever, Ctrl-C ends patrol.py at once and cancels its goal. The status
    # is recorded throughout: move_base drops an ended goal from its status list after 5 s
    # of sim time, which at speed 4 a poll could miss.
    status = ros.probe(["/move_base/status"], duration=300, timeout=300)
    patrol = ros.start(["rosrun", "patrolbot", "patrol.py"], name="patrol_forever")

    def seen(codes):
        return any(s["status"] in codes for m in status.messages() for s in m["msg"]["status_list"])

    ros.wait_for(lambda: seen({1}), 60, "patrol.py's goal to be active", 0.5)  # ACTIVE
    assert ros.stop(patrol, signal.SIGINT) == 0, ros.output(patrol)
    assert "the current goal is cancelled" in ros.output(patrol)
    # PREEMPTED (2) or RECALLED (8): the goal was cancelled, so the robot stops.
    ros.wait_for(lambda: seen({2, 8}), 60, "the goal to be cancelled", 0.5)
    status.stop()


MAZE = REPO / "catkin_ws/src/bullet_turtlebot/worlds/maze.yaml"


@pytest.mark.timeout(200)
def test_a_box_the_map_lacks_is_driven_around(ros, tmp_path):
    # The maze world with a box in the middle of the first corridor; amcl and move_base
    # get the maze's map without it. 0.3 m wide, it blocks the corridor's centre line and
    # leaves 0.475 m on each side of the 1.25 m corridor for the Kobuki (0.36 m); a 0.4 m
    # box left 0.065 m to spare, which the robot found only sometimes.
    box, size = (2.25, 0.75), 0.3
    world = tmp_path / "maze_with_box.yaml"
    world.write_text(
        MAZE.read_text().replace("image: maze.pgm", f"image: {MAZE.parent / 'maze.pgm'}")
        + f"boxes:\n  - {{pose: [{box[0]}, {box[1]}, 0], size: [{size}, {size}, 0.5]}}\n"
    )
    start_navigation(
        ros, "rosbook_demo", "amcl_demo.launch", f"world:={world}", f"map_file:={MAZE}"
    )
    records = run_client(ros, tmp_path, "--obstacle", f"{box[0]},{box[1]}", *goal_args(GOALS[:1]))
    (r,) = [r for r in records if "goal" in r]
    print(
        f"box: {r['state']} in {r['sim_seconds']:.1f} sim s, nearest approach of the robot's "
        f"centre to the box's centre {r['nearest_to_obstacle']:.2f} m"
    )
    assert r["state"] == "SUCCEEDED", r
    assert r["position_error"] <= GOAL_POSITION_LIMIT, r
    # Half the box plus the Kobuki's radius (0.18 m): closer would be a collision.
    assert r["nearest_to_obstacle"] > size / 2 + 0.18, r
