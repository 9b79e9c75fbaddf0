"""wander.py and friends on a plain roscore: synthetic scans with NaN and +/-inf, the book's
`./script.py cmd_vel:=...` form run from the scripts directory."""

import subprocess
import sys
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
PYTHON = "/usr/bin/python3"
FAKE_SCAN = [PYTHON, str(HERE / "fake_scan.py")]
sys.path.insert(0, str(HERE.parent / "tools"))
import lockstep  # noqa: E402

SLACK = lockstep.SLACK_TICKS
TICK = 0.1  # wander.py's period: one tick of the lock-step clock


def scripts_dir():
    done = subprocess.run(["rospack", "find", "wanderbot"], capture_output=True, text=True)
    return Path(done.stdout.strip()) / "scripts"


def phases(records):
    """[(state, start, end)] with state 'drive', 'spin' or 'stop', in sim time."""
    out = []
    for r in records:
        lin, ang = r["msg"]["linear"]["x"], r["msg"]["angular"]["z"]
        state = "drive" if lin > 0 else "spin" if ang != 0 else "stop"
        if out and out[-1][0] == state:
            out[-1][2] = r["clock"]
        else:
            out.append([state, r["clock"], r["clock"]])
    return out


def wander_on_scans(ros, ticks, *plan, params=()):
    """wander.py on sim time with a lock-step clock (one tick = its 0.1 s period) that
    publishes a synthetic scan a tick following `plan`; returns the clock's records."""
    ros.run(["rosparam", "set", "/use_sim_time", "true"])
    cmd = [PYTHON, str(HERE / "lockstep_scans.py"), "--ticks", str(ticks), *plan]
    clock = lockstep.launch(ros, cmd, "lockstep_scans")
    ros.start(["rosrun", "wanderbot", "wander.py", *params], name="wander")
    return lockstep.finish(ros, clock)


def test_wander_drives_past_nan_and_inf_and_spins_5_s_at_an_obstacle(ros):
    records = wander_on_scans(ros, 260, "clear@0", "near@3", "clear@4", "allnan@12", "clear@18")
    seen = phases(records)
    states = [s for s, _, _ in seen]
    assert states[:5] == ["drive", "spin", "drive", "spin", "drive"], seen
    assert {r["msg"]["linear"]["x"] for r in records} == {0.0, 0.4}
    assert {r["msg"]["angular"]["z"] for r in records} == {0.0, 1.0}
    first_spin, next_drive = seen[1], seen[2]
    assert first_spin[1] == pytest.approx(1003.0, abs=(1 + SLACK) * TICK)  # the near scan
    # A spin lasts until more than 5 s have passed on the node's clock: 5 s and a tick at
    # most, give or take the lock-step clock's slack.
    assert 5.0 - SLACK * TICK <= next_drive[1] - first_spin[1] <= 5.1 + SLACK * TICK
    # The all-NaN scan blocks: a second 5 s spin follows the first, and the robot drives
    # again after it, the scan having cleared at 18 s.
    allnan_spin = seen[3]
    assert allnan_spin[1] == pytest.approx(1012.0, abs=(1 + SLACK) * TICK)
    spun = next_drive_after(seen, 3) - allnan_spin[1]
    assert 10.0 - SLACK * TICK <= spun <= 10.2 + SLACK * TICK, seen


def next_drive_after(seen, index):
    return next(start for state, start, _ in seen[index:] if state == "drive")


def test_wander_treats_minus_inf_as_an_obstacle(ros):
    records = wander_on_scans(ros, 50, "far@0", "minus@3", params=["_forward_speed:=0.25"])
    seen = phases(records)
    assert [s for s, _, _ in seen][:2] == ["drive", "spin"], seen
    assert {r["msg"]["linear"]["x"] for r in records} == {0.0, 0.25}


def test_wander_rejects_a_bad_parameter(ros):
    done = ros.run(["rosrun", "wanderbot", "wander.py", "_min_range:=-1"], check=False)
    assert done.returncode == 2
    assert "~min_range must be > 0, got -1" in done.stdout + done.stderr


@pytest.mark.parametrize("script", ["red_light_green_light.py", "wander.py"])
def test_book_form_from_the_scripts_dir_with_remap(ros, script):
    ros.start(FAKE_SCAN + ["far@0"])
    ros.start([f"./{script}", "cmd_vel:=cmd_vel_mux/input/teleop"], cwd=scripts_dir(), name=script)
    msgs = ros.echo("cmd_vel_mux/input/teleop", count=5)
    assert {m["msg"]["linear"]["x"] for m in msgs} <= {0.0, 0.4, 0.5}
    assert "/cmd_vel" not in ros.topics()


def test_range_ahead_prints_the_book_line_and_handles_inf(ros):
    clear = ros.workdir / "clear-now"
    ros.start(FAKE_SCAN + ["far@0", f"clear@{clear}"])
    node = ros.start(["rosrun", "wanderbot", "range_ahead.py"], name="range_ahead")
    ros.wait_for(lambda: "range ahead: 2.0\n" in ros.output(node), 60, "the 2.0 m line")
    clear.touch()
    ros.wait_for(lambda: "nothing in range" in ros.output(node), 60, "the inf line")
    out = ros.output(node)
    assert "range ahead: 2.0\n" in out
    assert "Traceback" not in out
