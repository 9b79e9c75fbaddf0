"""score_slam's own part: the tuning it hands slam_offline (its figures come from rosbook_eval,
tested there and in tests/rosbook_eval)."""

import importlib.util
from pathlib import Path

import pytest


def load_score_slam():
    from importlib.machinery import SourceFileLoader

    script = Path(__file__).resolve().parent.parent / "scripts" / "score_slam"
    loader = SourceFileLoader("score_slam", str(script))
    score_slam = importlib.util.module_from_spec(
        importlib.util.spec_from_loader(loader.name, loader)
    )
    loader.exec_module(score_slam)
    return score_slam


def test_score_slam_starts_from_the_packages_turtlebot_tuning_file():
    score_slam = load_score_slam()
    tuning = dict(p.split("=", 1) for p in score_slam.turtlebot_tuning())
    assert tuning["srr"] == "0.01" and tuning["stt"] == "0.02"
    assert tuning["linearUpdate"] == "0.5" and tuning["angularUpdate"] == "0.436"
    assert tuning["maxUrange"] == "6.0" and tuning["minimumScore"] == "200"
    assert not {"particles", "base_frame", "odom_frame", "map_update_interval"} & set(tuning)
    # Found by package (rospkg), not next to the script: the same from the install space.
    assert score_slam.tuning_file().parts[-3:] == ("gmapping_lite", "config", "turtlebot.yaml")


def test_a_tuning_file_giving_a_key_twice_is_refused(tmp_path):
    tuning = tmp_path / "tuning.yaml"
    tuning.write_text("srr: 0.01\nstt: 0.02\nsrr: 0.1\n")
    with pytest.raises(SystemExit, match=r"tuning.yaml: key 'srr' given twice"):
        load_score_slam().turtlebot_tuning(tuning)
