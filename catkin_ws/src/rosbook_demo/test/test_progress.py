import math

from diagnostic_msgs.msg import DiagnosticStatus, KeyValue
from rosbook_demo.progress import (
    ProgressMeter,
    died_nodes,
    slam_scan_counts,
    slam_skip_warning,
)


def test_progress_line_reports_speedup_and_distance():
    meter = ProgressMeter(sim_seconds=100, wall_start=0.0, sim_start=10.0)
    meter.add_position(0.0, 0.0)
    meter.add_position(3.0, 4.0)
    meter.add_position(float("nan"), 0.0)  # ignored
    line = meter.line(sim_now=60.0, wall_now=5.0, known_area_m2=12.5)
    assert "50/100 s simulated" in line
    assert "10.0x real time" in line
    assert "travelled    5.0 m" in line
    assert "12.5 m² known" in line
    assert math.isclose(meter.distance, 5.0)


def test_speed_warning_only_when_clearly_below_the_speed_asked():
    meter = ProgressMeter(sim_seconds=100, wall_start=0.0, sim_start=0.0)
    assert meter.speed_held(sim_now=50.0, wall_now=10.0) == 5.0
    assert meter.speed_warning(sim_now=50.0, wall_now=10.0, asked=5.0) is None
    assert meter.speed_warning(sim_now=42.0, wall_now=10.0, asked=5.0) is None  # 84 %
    warning = meter.speed_warning(sim_now=30.0, wall_now=10.0, asked=5.0)
    assert "3.0x" in warning and "5x asked" in warning and "--speed" in warning
    assert (
        meter.speed_warning(sim_now=30.0, wall_now=10.0, asked=0.0) is None
    )  # as fast as possible


def scans_status(name, **values):
    keys = {"received": "scans received", "skipped": "scans skipped (fell behind)"}
    return DiagnosticStatus(
        name=name, values=[KeyValue(key=keys[k], value=str(v)) for k, v in values.items()]
    )


def test_slam_skip_warning_names_the_share_skipped_and_the_fix():
    counts = slam_scan_counts(scans_status("/slam_gmapping: scans", received=400, skipped=100))
    assert counts == {"scans received": 400, "scans skipped (fell behind)": 100}
    warning = slam_skip_warning(counts)
    assert "skipped 100 of 400 scans (25%)" in warning and "--speed" in warning
    kept_up = slam_scan_counts(scans_status("/slam_gmapping: scans", received=400, skipped=0))
    assert slam_skip_warning(kept_up) is None
    assert slam_skip_warning(None) is None
    # Other nodes' statuses, or a status without the counts, are not slam_gmapping's.
    assert slam_scan_counts(scans_status("/other: motors", received=1, skipped=1)) is None
    assert slam_scan_counts(scans_status("/slam_gmapping: scans", received=4)) is None


def test_died_nodes_names_the_required_nodes_roslaunch_saw_die():
    log = (
        "process[slam_gmapping-3]: started with pid [41]\n"
        "================================================================================"
        "REQUIRED process [slam_gmapping-3] has died!\n"
        "process has died [pid 41, exit code -9, cmd ...].\n"
        "REQUIRED process [slam_gmapping-3] has died!\n"
        "REQUIRED process [record-5] has died!\n"
    )
    assert died_nodes(log) == ["slam_gmapping", "record"]
    assert died_nodes("all is well\n") == []


def test_died_nodes_can_name_any_node_that_died():
    log = (
        "process[map_server-4]: started with pid [27893]\n"
        "\x1b[31m[map_server-4] process has died [pid 27893, exit code 1, cmd ...].\n"
    )
    assert died_nodes(log) == []
    assert died_nodes(log, required_only=False) == ["map_server"]
