"""wander.py and friends on a plain roscore: synthetic scans with NaN and +/-inf, the book's
`./script.py cmd_vel:=...` form run from the scripts directory."""

import subprocess
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
FAKE_SCAN = ["/usr/bin/python3", str(HERE / "fake_scan.py")]


def scripts_dir():
    done = subprocess.run(["rospack", "find", "wanderbot"], capture_output=True, text=True)
    return Path(done.stdout.strip()) / "scripts"


def phases(messages):
    """[(state, start, end)] with state 'drive', 'spin' or 'stop'."""
    out = []
    for m in messages:
        lin, ang = m["msg"]["linear"]["x"], m["msg"]["angular"]["z"]
        state = "drive" if lin > 0 else "spin" if ang != 0 else "stop"
        if out and out[-1][0] == state:
            out[-1][2] = m["ros"]
        else:
            out.append([state, m["ros"], m["ros"]])
    return out


def test_wander_drives_past_nan_and_inf_and_spins_5_s_at_an_obstacle(ros):
    # The scan timeline starts once wander is running and recorded (wander waits for a scan).
    ros.start(["rosrun", "wanderbot", "wander.py"], name="wander")
    ros.wait_for_topic("cmd_vel")
    probe = ros.probe(["cmd_vel"], duration=26)
    ros.start(FAKE_SCAN + ["clear@0", "near@3", "clear@4", "allnan@12", "clear@18"])
    messages = probe.wait(40)
    seen = phases(messages)
    states = [s for s, _, _ in seen]
    assert states[:5] == ["drive", "spin", "drive", "spin", "drive"], seen
    assert {m["msg"]["linear"]["x"] for m in messages} == {0.0, 0.4}
    assert {m["msg"]["angular"]["z"] for m in messages} == {0.0, 1.0}
    first_spin = seen[1]
    next_drive = seen[2]
    assert next_drive[1] - first_spin[1] == pytest.approx(5.0, abs=0.25)
    # the all-NaN scan blocks: spinning continues (in 5 s bouts) until it clears at 18 s
    allnan_spin = seen[3]
    assert allnan_spin[2] - allnan_spin[1] >= 5.5


def test_wander_treats_minus_inf_as_an_obstacle(ros):
    ros.start(["rosrun", "wanderbot", "wander.py", "_forward_speed:=0.25"], name="wander")
    ros.wait_for_topic("cmd_vel")
    probe = ros.probe(["cmd_vel"], duration=10)
    ros.start(FAKE_SCAN + ["far@0", "minus@3"])
    seen = phases(probe.wait(40))
    assert [s for s, _, _ in seen][:2] == ["drive", "spin"], seen


def test_wander_rejects_a_bad_parameter(ros):
    done = ros.run(["rosrun", "wanderbot", "wander.py", "_min_range:=-1"], check=False)
    assert done.returncode == 2
    assert "~min_range must be finite and > 0" in done.stdout + done.stderr


@pytest.mark.parametrize("script", ["red_light_green_light.py", "wander.py"])
def test_book_form_from_the_scripts_dir_with_remap(ros, script):
    ros.start(FAKE_SCAN + ["far@0"])
    ros.start([f"./{script}", "cmd_vel:=cmd_vel_mux/input/teleop"], cwd=scripts_dir(), name=script)
    msgs = ros.echo("cmd_vel_mux/input/teleop", count=5)
    assert {m["msg"]["linear"]["x"] for m in msgs} <= {0.0, 0.4, 0.5}
    assert "/cmd_vel" not in ros.topics()


def test_range_ahead_prints_the_book_line_and_handles_inf(ros):
    ros.start(FAKE_SCAN + ["far@0", "clear@2"])
    node = ros.start(["rosrun", "wanderbot", "range_ahead.py"], name="range_ahead")
    ros.wait_for(lambda: "nothing in range" in ros.output(node), 30, "the inf line")
    out = ros.output(node)
    assert "range ahead: 2.0\n" in out
    assert "Traceback" not in out
