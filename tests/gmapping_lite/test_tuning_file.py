"""The Turtlebot tuning has one copy, gmapping_lite's config/turtlebot.yaml: every launch file
that starts slam_gmapping loads it, and its values reach the node unless the launch file sets
its own after it (the main job's particle count, map interval and map bounds)."""

import subprocess
from pathlib import Path

import pytest
import yaml
from rospkg import RosPack

REPO = Path(__file__).resolve().parents[2]
TUNING = Path(RosPack().get_path("gmapping_lite")) / "config" / "turtlebot.yaml"
MAIN_JOB = {"particles": 30, "map_update_interval": 2.0}
# Launch file (package, name, arguments) -> what it sets over the tuning file.
LAUNCHES = {
    ("gmapping_lite", "gmapping_turtlebot.launch", ()): {},
    ("gmapping_lite", "gmapping_turtlebot.launch", ("particles:=50",)): {"particles": 50},
    ("rosbook_demo", "mapping_from_bag.launch", ("bag:=/tmp/data.bag",)): {},
    ("rosbook_demo", "mapping_live.launch", ()): MAIN_JOB,
    ("explorer", "explore_sim.launch", ()): {
        **MAIN_JOB,
        **{"xmin": -20.0, "ymin": -20.0, "xmax": 20.0, "ymax": 20.0},
    },
}


def test_every_launch_file_starting_slam_gmapping_is_checked_here():
    starting = {
        path.name
        for path in (REPO / "catkin_ws" / "src").glob("**/launch/*.launch")
        if 'type="slam_gmapping"' in path.read_text()
    }
    # Checked too: mapping_live.launch, which starts it through explore_sim.launch.
    assert starting | {"mapping_live.launch"} == {name for _, name, _ in LAUNCHES}


@pytest.mark.parametrize("launch", sorted(LAUNCHES), ids=lambda k: " ".join([k[1], *k[2]]))
def test_launch_file_gives_slam_gmapping_the_tuning_files_values(launch):
    package, name, args = launch
    done = subprocess.run(
        ["roslaunch", "--dump-params", package, name, *args],
        capture_output=True,
        text=True,
        timeout=120,
        check=True,
    )
    params = yaml.safe_load(done.stdout)
    expected = {**yaml.safe_load(TUNING.read_text()), **LAUNCHES[launch]}
    got = {key: params.get(f"/slam_gmapping/{key}") for key in expected}
    assert got == expected
