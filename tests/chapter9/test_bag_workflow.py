"""Chapter 9 end to end, with the book's own commands: record a bag of /scan and /tf from the
simulated Turtlebot, stop the simulator, build a map from the bag with slam_gmapping under
sim time, save it with map_saver, serve it with map_server, and check it against the world.
"""

import math
import re
import signal
import xmlrpc.client
from pathlib import Path

import numpy as np
import pytest
from map_server.map_io import load_map
from rosbook_eval.grids import near_wall_share, occupied_points
from rosbook_eval.scoring import place_grid
from rosbook_eval.truth import truth_grid
from roskit import launched_from_shell, run_in_ros_home

SIM_SECONDS = 150.0
SPEED = 5.0
START = (-8.5, 0.0, 0.0)  # the office world's start pose: where SLAM's map frame lies


def clock(ros):
    return ros.sim_time()


def scans_dropped(ros, node="/slam_gmapping"):
    """Scans that `node`'s /scan queue dropped, as its getBusStats (roscpp) counts them."""
    master = xmlrpc.client.ServerProxy(ros.env["ROS_MASTER_URI"])
    _, _, uri = master.lookupNode("/chapter9_tests", node)
    # roscpp answers [publications, subscriptions] (rospy: [code, message, stats])
    _, subscriptions = xmlrpc.client.ServerProxy(uri).getBusStats("/chapter9_tests")
    return sum(c[3] for topic, conns in subscriptions if topic == "/scan" for c in conns)


def messages_received(ros, node, topic):
    """Messages of `topic` that `node` (roscpp) has received, from its getBusStats."""
    master = xmlrpc.client.ServerProxy(ros.env["ROS_MASTER_URI"])
    _, _, uri = master.lookupNode("/chapter9_tests", node)
    _, subscriptions = xmlrpc.client.ServerProxy(uri).getBusStats("/chapter9_tests")
    return sum(c[2] for name, conns in subscriptions if name == topic for c in conns)


def map_from_bag(ros, bag):
    """The book's `rosrun gmapping slam_gmapping` and `rosbag play --clock data.bag`, played
    as fast as slam_gmapping keeps up: a loaded machine makes it drop scans from its queue
    (the map is then judged on part of the data), and the bag is played again, slower, by a
    fresh slam_gmapping. Returns that node, still running."""
    for rate in (SPEED, 2.0, 1.0, 0.5):
        slam = ros.start(["rosrun", "gmapping", "slam_gmapping"], name="slam_gmapping")
        ros.wait_for(lambda: ros.subscribes("/slam_gmapping", "/scan", "/tf"), 60, "slam")
        # Played once slam_gmapping is connected to /scan and /tf.
        cmd = ["rosbag", "play", "--clock", "--wait-for-subscribers", "-r", str(rate), bag]
        play = ros.start(cmd, name="play")
        assert play.wait(timeout=SIM_SECONDS / rate * 6 + 60) == 0, ros.output(play)
        assert slam.poll() is None, ros.output(slam)
        dropped = scans_dropped(ros)
        print(f"rosbag play -r {rate}: slam_gmapping dropped {dropped} scans")
        if dropped == 0:
            return slam
        ros.stop(slam)
    raise AssertionError(f"slam_gmapping dropped scans even at -r {rate}")


def record_office_bag(ros, tmp_path):
    """The book's step 1: drive around while `rosbag record -O data.bag /scan /tf` runs."""
    sim = ros.start(
        [
            "roslaunch",
            "turtlebot_stage",
            "turtlebot_in_stage.launch",
            "world:=office",
            "rviz:=false",
            f"speed:={SPEED}",
            "seed:=3",
            # The simulator alone: chapter 10's amcl would put its map -> odom in the bag.
            "nav:=false",
        ],
        name="sim",
    )
    ros.wait_for_topic("/scan", timeout=60)
    wander = ros.start(
        ["rosrun", "wanderbot", "wander.py", "cmd_vel:=cmd_vel_mux/input/teleop"], name="wander"
    )
    recorder = ros.start(["rosbag", "record", "-O", "data.bag", "/scan", "/tf"], name="record")
    ros.wait_for(lambda: (tmp_path / "data.bag.active").exists(), 30, "rosbag record to start")
    start = clock(ros)
    ros.wait_for(
        lambda: clock(ros) >= start + SIM_SECONDS,
        SIM_SECONDS / SPEED * 4 + 60,
        f"{SIM_SECONDS} s of simulated driving",
    )
    ros.stop(recorder)
    ros.wait_for(lambda: (tmp_path / "data.bag").exists(), 60, "data.bag to be closed")
    # The book stops the simulator so that its scans do not mix with the bag's.
    ros.stop(wander)
    ros.stop(sim)
    return tmp_path / "data.bag"


@pytest.mark.slow
@pytest.mark.timeout(1800)  # 150 sim s recorded at 5x, then played up to four times
def test_record_map_save_serve_and_score(ros, tmp_path):
    bag = record_office_bag(ros, tmp_path)

    info = ros.run(["rosbag", "info", str(bag)]).stdout
    assert re.search(r"/scan\s+(\d+) msgs\s+: sensor_msgs/LaserScan", info), info
    assert re.search(r"/tf\s+(\d+) msgs\s+: tf2_msgs/TFMessage", info), info
    scans = int(re.search(r"/scan\s+(\d+) msgs", info).group(1))
    assert scans >= 0.9 * 10 * SIM_SECONDS  # 10 Hz scan

    # The book's step 2, with the parameter changes it recommends for the Turtlebot.
    ros.run(["rosparam", "set", "use_sim_time", "true"])
    for name, value in [
        ("angularUpdate", 0.1),
        ("linearUpdate", 0.1),
        ("lskip", 10),
        ("xmax", 10),
        ("xmin", -10),
        ("ymax", 10),
        ("ymin", -10),
        ("base_frame", "base_footprint"),
    ]:
        ros.run(["rosparam", "set", f"/slam_gmapping/{name}", str(value)])
    slam = map_from_bag(ros, bag)

    # Step 3: save it while slam_gmapping still runs.
    saved = ros.run(["rosrun", "map_server", "map_saver", "-f", "office_map"], timeout=90)
    assert "office_map.pgm" in saved.stdout + saved.stderr
    yaml_text = (tmp_path / "office_map.yaml").read_text()
    for key in (
        "image: office_map.pgm",
        "resolution: 0.050000",
        "negate: 0",
        "occupied_thresh: 0.65",
        "free_thresh: 0.196",
    ):
        assert key in yaml_text, yaml_text
    saved_map = load_map(str(tmp_path / "office_map.yaml"))
    assert saved_map.resolution == 0.05
    # The book's bounds, 20 m x 20 m around the start, grown where the robot drove beyond.
    assert saved_map.width >= 400 and saved_map.height >= 400
    assert saved_map.origin[0] <= -10.0 and saved_map.origin[1] <= -10.0
    ros.stop(slam, sig=signal.SIGINT)

    # Step 4: serve the saved map and compare it cell by cell.
    ros.start(["rosrun", "map_server", "map_server", "office_map.yaml"], name="map_server")
    served = ros.echo("/map", count=1, timeout=30)[0]["msg"]
    info_msg = served["info"]
    assert (info_msg["width"], info_msg["height"]) == (saved_map.width, saved_map.height)
    assert math.isclose(info_msg["resolution"], 0.05, rel_tol=1e-6)
    assert np.array_equal(np.array(served["data"], dtype=np.int8), saved_map.flat())
    metadata = ros.echo("/map_metadata", count=1)[0]["msg"]
    assert metadata["width"] == saved_map.width

    # Accuracy: the book's bag holds no ground truth, so the map frame is placed where the
    # robot started in the world (the true start pose), and judged by the project's metric.
    truth = truth_grid("office")
    saved = (saved_map.data, saved_map.resolution, saved_map.origin)
    walls = occupied_points(place_grid(saved, START))
    assert len(walls) > 500, "the map shows almost no walls"
    share = near_wall_share(walls, truth, 0.10)
    print(f"chapter 9 bag workflow: {len(walls)} wall cells, {100 * share:.1f}% within 0.10 m")
    # A wandering robot, the book's parameters and drifting odometry: the project's
    # measured figure is in the README; 65% still rules out a wrong frame or a smeared map.
    assert share >= 0.65
    known = np.count_nonzero(saved_map.data == 0) * 0.05**2
    assert known > 40.0, f"only {known:.1f} m² mapped as free"


def test_book_bag_holds_the_whole_tf_chain(ros, tmp_path):
    """`rosbag record /scan /tf` must be enough: the bag carries base_footprint → laser."""
    bag = Path(tmp_path / "data.bag")
    sim = ros.start(
        ["roslaunch", "turtlebot_gazebo", "turtlebot_playground.launch", f"speed:={SPEED}"],
        name="sim",
    )
    ros.wait_for_topic("/scan", timeout=60)
    recorder = ros.start(["rosbag", "record", "-O", str(bag), "/scan", "/tf"], name="record")
    ros.wait_for(lambda: Path(str(bag) + ".active").exists(), 30, "rosbag record to start")
    start = clock(ros)
    ros.wait_for(lambda: clock(ros) >= start + 5.0, 120, "5 s of sim time")
    ros.stop(recorder)
    # rosbag's recording child closes (renames) the bag after the wrapper has exited.
    ros.wait_for(bag.exists, 60, "the bag to be closed")
    ros.stop(sim)
    import rosbag

    edges = set()
    with rosbag.Bag(str(bag)) as recorded:
        for _, msg, _ in recorded.read_messages(["/tf"]):
            edges |= {(t.header.frame_id, t.child_frame_id) for t in msg.transforms}
    chain = [("odom", "base_footprint"), ("base_footprint", "base_link")]
    for edge in chain:
        assert edge in edges, edges
    children = {child for _, child in edges}
    assert "camera_depth_frame" in children, edges


def test_relative_bag_argument_means_the_launching_shell_folder(ros, tmp_path):
    """`bag:=data.bag` of our launch files (rosbook_env's rosbag_here): recorded into, and
    played from, the folder roslaunch was started in, not roslaunch's ~/.ros."""
    shell, ros_home, env = launched_from_shell(ros, tmp_path)
    record = tmp_path / "record.launch"
    record.write_text(
        '<launch><arg name="bag"/>'
        '<node pkg="rostopic" type="rostopic" name="talker" args="pub -r 20 /chatter '
        'std_msgs/String hello"/>'
        '<node pkg="rosbook_env" type="rosbag_here" name="record" output="screen" '
        "args=\"record -O '$(arg bag)' /chatter\"/></launch>"
    )
    recording = ros.start(["roslaunch", str(record), "bag:=data.bag"], env=env, cwd=shell)
    ros.wait_for(lambda: (shell / "data.bag.active").exists(), 60, "recording into shell/")
    ros.wait_for(lambda: ros.subscribes("/record", "/chatter"), 60, "record to subscribe")
    ros.wait_for(lambda: messages_received(ros, "/record", "/chatter") >= 5, 60, "messages")
    ros.stop(recording, timeout=30)
    assert f"recording to {shell / 'data.bag'}" in ros.output(recording)
    ros.wait_for(lambda: (shell / "data.bag").exists(), 60, "data.bag to be closed")
    assert not list(ros_home.glob("*.bag*"))

    play = tmp_path / "play.launch"
    play.write_text(
        '<launch><arg name="bag"/><node pkg="rosbook_env" type="rosbag_here" name="play" '
        'output="screen" required="true" args="play --rate=20 \'$(arg bag)\'"/></launch>'
    )
    playing = ros.start(["roslaunch", str(play), "bag:=data.bag"], env=env, cwd=shell)
    assert playing.wait(timeout=120) == 0, ros.output(playing)
    assert f"playing {shell / 'data.bag'}" in ros.output(playing)

    # Found nowhere: the error names both folders and the fix, and rosbag is not started.
    done = run_in_ros_home(
        ["rosrun", "rosbook_env", "rosbag_here", "play", "gone.bag"], env, ros_home
    )
    assert done.returncode == 1
    assert f"gone.bag: bag file not found (looked in {ros_home} and {shell}" in done.stderr
    assert "bag:=$(pwd)/data.bag" in done.stderr
