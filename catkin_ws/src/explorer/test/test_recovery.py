import math

from explorer.recovery import Blacklist, Recovery, RecoveryParams, StuckMonitor


def test_stuck_when_not_moving_for_the_window():
    monitor = StuckMonitor(window=5.0, min_motion=0.1, min_turn=0.5)
    stuck = [monitor.update(t * 0.1, 1.0, 2.0, 0.3) for t in range(60)]
    assert not any(stuck[:45]) and stuck[-1]


def test_progress_or_turning_is_not_stuck():
    moving = StuckMonitor(window=5.0)
    assert not any(moving.update(t * 0.1, t * 0.01, 0.0, 0.0) for t in range(100))
    turning = StuckMonitor(window=5.0)
    assert not any(turning.update(t * 0.1, 0.0, 0.0, math.sin(t * 0.05)) for t in range(100))


def test_reset_forgets_history():
    monitor = StuckMonitor(window=2.0)
    for t in range(30):
        monitor.update(t * 0.1, 0.0, 0.0, 0.0)
    monitor.reset()
    assert not monitor.update(3.0, 0.0, 0.0, 0.0)


def test_recovery_backs_up_then_turns_then_finishes():
    params = RecoveryParams(backup_speed=0.1, backup_time=1.0, turn_speed=0.8, turn_time=2.0)
    recovery = Recovery(10.0, turn_sign=-1, params=params)
    assert recovery.command(10.5) == (-0.1, 0.0, False)
    assert recovery.command(11.5) == (0.0, -0.8, False)
    assert recovery.command(13.1) == (0.0, 0.0, True)


def test_blacklist_entries_expire():
    blacklist = Blacklist(radius=0.5, timeout=30.0)
    blacklist.add(1.0, 2.0, now=100.0)
    assert blacklist.active(120.0) == [(1.0, 2.0)]
    assert blacklist.active(131.0) == []
