"""Issue 14 item 6: amcl finds the robot from no idea where it is (global localization).
The simulator in the maze, map_server with the maze's map and amcl_lite (amcl.launch, the
Turtlebot tuning, fixed seeds) are told a start pose that is wrong; global_localization is
called and the robot turns in place, then wanders, as a user would with teleop, until
amcl's estimate has held on the simulator's ground truth. Everything in sim time."""

from pathlib import Path

import pytest
import yaml
from roskit import read_jsonl

HERE = Path(__file__).resolve().parent
REPO = HERE.parent.parent
MAZE = REPO / "catkin_ws/src/bullet_turtlebot/worlds/maze.yaml"
AMCL_LAUNCH = REPO / "catkin_ws/src/amcl_lite/launch/amcl.launch"
SPEED = 4
# The robot's true start: a corridor cell of the maze's 1.5 m grid far from the world's
# start (0.75, 0.75, 0), which is what amcl is told.
TRUE_START = (8.25, 3.75, 2.0)
# Converged: within one KLD histogram bin's half-width of the truth (amcl's 0.5 m x 10
# degree bins, the resolution at which the filter tells poses apart and clusters them)...
CONVERGED_POSITION = 0.25  # m
CONVERGED_YAW = 0.3  # rad: 10 degree bins, and the Kinect's view is 58 degrees wide
# ... and then holding it for this long (a full turn at the client's 0.8 rad/s).
HOLD = 8.0  # sim s of driving
# Tracking limit once converged, as test_navigation holds amcl to from a known pose.
TRACKING_LIMIT = 0.2  # m
DRIVE = 90.0  # sim s of driving at most: a full turn, then wandering


@pytest.mark.timeout(240)
def test_global_localization_converges_on_the_true_pose_and_the_cloud_shrinks(ros, tmp_path):
    told = yaml.safe_load(MAZE.read_text())["start"]
    ros.run(["rosparam", "set", "/amcl/seed", "3"])
    ros.start(
        [
            "roslaunch",
            "bullet_turtlebot",
            "simulator.launch",
            "world:=maze",
            f"x:={TRUE_START[0]}",
            f"y:={TRUE_START[1]}",
            f"yaw:={TRUE_START[2]}",
            f"speed:={SPEED}",
            "seed:=1",
            "wait_for_commands:=0.3",
        ],
        name="simulator",
    )
    ros.start(["rosrun", "map_server", "map_server", str(MAZE)], name="map_server")
    ros.start(
        ["roslaunch", "amcl_lite", "amcl.launch"]
        + [f"initial_pose_{k}:={v}" for k, v in zip("xya", told, strict=True)],
        name="amcl",
    )
    ros.wait_for_service("global_localization", timeout=90)
    out = tmp_path / "global.jsonl"
    client = ros.start(
        [
            "/usr/bin/python3",
            str(HERE / "global_loc_client.py"),
            "--out",
            str(out),
            "--global-localization",
            "--duration",
            str(DRIVE),
            "--tolerance",
            str(CONVERGED_POSITION),
            "--yaw-tolerance",
            str(CONVERGED_YAW),
            "--hold",
            str(HOLD),
        ],
        name="global_loc_client",
    )
    ros.wait_for(lambda: client.poll() is not None, 180, "the driving client", interval=0.5)
    assert client.returncode == 0, ros.output(client)[-3000:]
    records = read_jsonl(out)
    updates = [r for r in records if "t" in r]
    summary = records[-1]
    print(
        f"converged after {summary['converged_after']} sim s, last error "
        f"{summary['last_error']:.3f} m / {summary['last_yaw_error']:.3f} rad, particles "
        f"{[u['particles'] for u in updates[:3]]} ... {updates[-1]['particles']}"
    )
    assert summary["converged_after"] is not None, updates[-10:]
    assert summary["driven"] - summary["converged_after"] >= HOLD, summary
    assert summary["last_error"] <= TRACKING_LIMIT, summary
    assert summary["last_yaw_error"] <= CONVERGED_YAW, summary
    # The cloud spread over the maze (more than max_particles: global localization's
    # cloud) shrank to max_particles or fewer once amcl knew where the robot was.
    max_particles = int(
        next(
            line.split('value="')[1].split('"')[0]
            for line in AMCL_LAUNCH.read_text().splitlines()
            if 'name="max_particles"' in line
        )
    )
    counts = [u["particles"] for u in updates if u["particles"] is not None]
    assert max(counts) > max_particles, counts[:5]
    assert counts[-1] <= max_particles, counts[-5:]
