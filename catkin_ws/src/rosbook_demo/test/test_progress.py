import math

from rosbook_demo.progress import ProgressMeter


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
