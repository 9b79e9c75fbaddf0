"""score_slam's maths: map loading, alignment, trajectory and map error (no ROS)."""

import importlib.util
import math
from pathlib import Path

import numpy as np
import pytest

_spec = importlib.util.spec_from_file_location(
    "gmapping_lite_scoring",
    Path(__file__).resolve().parent.parent / "src" / "gmapping_lite_scoring.py",
)
scoring = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(scoring)


def write_map(tmp_path, pixels, origin=(-1.0, -2.0), resolution=0.1):
    h, w = pixels.shape
    (tmp_path / "t.pgm").write_bytes(f"P5\n# c\n{w} {h}\n255\n".encode() + pixels.tobytes())
    (tmp_path / "t.yaml").write_text(
        f"image: t.pgm\nresolution: {resolution}\norigin: [{origin[0]}, {origin[1]}, 0]\n"
        "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n"
    )
    return tmp_path / "t.yaml"


def test_map_yaml_is_read_bottom_up_with_trinary_values(tmp_path):
    pixels = np.full((3, 4), 254, dtype=np.uint8)
    pixels[0, 0] = 0  # top-left of the image: the map's highest row
    pixels[2, 3] = 205
    m = scoring.load_map_yaml(write_map(tmp_path, pixels))
    assert m["origin"] == [-1.0, -2.0]
    assert m["grid"][2, 0] == 100
    assert m["grid"][0, 3] == -1
    assert m["grid"][1, 1] == 0


def test_alignment_places_odometry_frame_by_the_true_start():
    to_world = scoring.align_to_first((5.0, 1.0, math.pi / 2), (0.0, 0.0, 0.0))
    xy = scoring.transform_points(to_world, [(1.0, 0.0)])
    assert xy[0] == pytest.approx([5.0, 2.0])


def test_best_fit_alignment_recovers_a_rigid_motion():
    t = np.arange(0, 20, 1.0)
    truth = np.column_stack([t, np.cos(t / 3) * 4, np.sin(t / 2) * 3, np.zeros_like(t)])
    # The same path seen from a frame turned by 0.3 rad and moved by (2, -1).
    c, s = math.cos(-0.3), math.sin(-0.3)
    x, y = truth[:, 1] - 2.0, truth[:, 2] + 1.0
    est = np.column_stack([t, c * x - s * y, s * x + c * y, np.zeros_like(t)])
    to_world = scoring.align_best_fit(est, truth)
    assert to_world == pytest.approx((2.0, -1.0, 0.3))
    rms, worst = scoring.trajectory_error(est, truth, to_world)
    assert rms == pytest.approx(0.0, abs=1e-9)


def test_trajectory_error_of_a_shifted_path():
    t = np.arange(0, 10, 1.0)
    truth = np.column_stack([t, t * 0.1, np.zeros_like(t), np.zeros_like(t)])
    est = truth.copy()
    est[:, 2] += 0.05
    rms, worst = scoring.trajectory_error(est, truth, (0.0, 0.0, 0.0))
    assert rms == pytest.approx(0.05)
    assert worst == pytest.approx(0.05)


def test_map_accuracy_counts_cells_near_true_walls():
    grid = np.zeros((20, 20), dtype=np.int16)
    grid[:, 10] = 100  # a wall covering x in [1.0, 1.1)
    truth = {"resolution": 0.1, "origin": [0.0, 0.0], "grid": grid}
    points = np.array([[1.05, 1.0], [1.18, 1.0], [1.5, 1.0], [0.5, 0.5]])
    assert scoring.map_accuracy(points, truth, 0.10) == pytest.approx(0.5)


def test_world_primitives_are_drawn_in():
    truth = {"resolution": 0.1, "origin": [0.0, 0.0], "grid": np.zeros((30, 30), np.int16)}
    world = {
        "boxes": [{"pose": [1.0, 1.0, 0], "size": [0.4, 0.2, 1]}],
        "cylinders": [{"position": [2.0, 2.0], "radius": 0.3}],
    }
    scoring.rasterize_primitives(truth, world)
    assert truth["grid"][10, 10] == 100
    assert truth["grid"][20, 20] == 100
    assert truth["grid"][5, 25] == 0


def test_score_slam_starts_from_the_turtlebot_launch_files_tuning():
    from importlib.machinery import SourceFileLoader

    script = Path(__file__).resolve().parent.parent / "scripts" / "score_slam"
    loader = SourceFileLoader("score_slam", str(script))
    score_slam = importlib.util.module_from_spec(
        importlib.util.spec_from_loader(loader.name, loader)
    )
    loader.exec_module(score_slam)
    tuning = dict(p.split("=", 1) for p in score_slam.turtlebot_tuning())
    assert tuning["srr"] == "0.01" and tuning["stt"] == "0.02"
    assert tuning["linearUpdate"] == "0.5" and tuning["angularUpdate"] == "0.436"
    assert tuning["maxUrange"] == "6.0" and tuning["minimumScore"] == "200"
    assert not {"particles", "base_frame", "odom_frame", "map_update_interval"} & set(tuning)
