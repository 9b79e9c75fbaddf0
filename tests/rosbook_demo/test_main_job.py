"""The main job end to end, as `make demo` runs it: scripts/demo.sh explores, maps, saves the
map with map_saver, scores it against ground truth and draws the overlay. A short run
(120 sim s) checks every product and that the figures say what a working SLAM says."""

import json
import os
import re
import signal
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "tests"))
from roskit import descendants, kill_tree, ros_environment, wait_until  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from demo_run import SIM_SECONDS, run_demo  # noqa: E402


@pytest.fixture(scope="module")
def main_job(tmp_path_factory):
    out = tmp_path_factory.mktemp("main job") / "out dir"  # spaces in the path on purpose
    done = run_demo(out)
    return done, out


@pytest.mark.slow
@pytest.mark.timeout(960)
def test_demo_writes_the_map_overlay_and_figures(main_job):
    done, out = main_job
    assert done.returncode == 0, done.stdout[-4000:] + done.stderr[-4000:]
    for name in ("office_map.pgm", "office_map.yaml", "office_truth.yaml", "office.bag"):
        assert (out / name).stat().st_size > 0, name
    assert not list(out.glob("*.partial.bag*"))  # the completed run's bag moved into place
    png = (out / "office_overlay.png").read_bytes()
    assert png.startswith(b"\x89PNG\r\n\x1a\n") and len(png) > 10_000
    # The map map_saver wrote loads with map_server's reader and is the book's trinary map.
    from map_server.map_io import load_map

    saved = load_map(str(out / "office_map.yaml"))
    assert 0.01 <= saved.resolution <= 0.1
    assert {-1, 0, 100} >= set(int(v) for v in set(saved.data.flatten().tolist()))


@pytest.mark.slow
@pytest.mark.timeout(960)
def test_demo_prints_progress_and_sane_figures(main_job):
    done, out = main_job
    assert done.returncode == 0, done.stdout[-4000:] + done.stderr[-4000:]
    progress = [line for line in done.stdout.splitlines() if "s simulated" in line]
    assert len(progress) >= 3, done.stdout  # a line every 30 sim s over 120 s
    figures = json.loads((out / "figures.json").read_text())
    # The explorer drives at up to 0.3-0.5 m/s: in 120 s it covers well over 10 m.
    assert figures["distance_m"] >= 10.0, figures
    # SLAM corrects odometry's drift: its error is small in absolute terms and it maps walls
    # where the walls are. Bounds are loose (a short run, any machine load), yet a broken
    # SLAM, scorer or frame convention fails them by an order of magnitude.
    assert figures["slam_rms_m"] < 0.25, figures
    assert figures["walls_within_tolerance"] >= 0.7, figures
    for key, value in figures.items():
        if isinstance(value, float):
            assert value == value and abs(value) != float("inf"), (key, value)


@pytest.mark.slow
@pytest.mark.timeout(960)
def test_demo_stops_the_clock_when_the_time_is_up(main_job):
    # Saving the map takes wall seconds; at 4x they used to add minutes of driving to the bag
    # and the figures. The simulator is paused first, so nothing is recorded after that time.
    done, out = main_job
    assert done.returncode == 0, done.stdout[-4000:] + done.stderr[-4000:]
    paused = re.search(r"simulation paused at ([0-9.]+) s of sim time", done.stdout)
    assert paused, done.stdout
    import rosbag

    with rosbag.Bag(str(out / "office.bag")) as bag:
        start, end = bag.get_start_time(), bag.get_end_time()
    paused_at = float(paused.group(1))
    assert paused_at - start >= SIM_SECONDS / 2, (start, paused_at)  # the bag starts late
    assert end <= paused_at + 1e-3, (end, paused_at)


def test_demo_rejects_nonsense_arguments(tmp_path):
    env = dict(os.environ, PYENV_VERSION="system")
    done = subprocess.run(
        [str(REPO / "scripts" / "demo.sh"), "--sim-seconds", "-5", "--out", str(tmp_path)],
        capture_output=True,
        text=True,
        timeout=120,
        env=env,
        stdin=subprocess.DEVNULL,
    )
    assert done.returncode == 2
    assert "--sim-seconds" in done.stderr


def start_long_demo(out, logs):
    """The main job with an hour of sim time (long enough to be interrupted), its own
    roscore, progress every 2 sim s; its output in the files logs/stdout and logs/stderr."""
    env = ros_environment(0)
    env.pop("ROS_MASTER_URI")
    with open(logs / "stdout", "w") as stdout, open(logs / "stderr", "w") as stderr:
        return subprocess.Popen(
            ["rosrun", "rosbook_demo", "mapping_demo", "--sim-seconds", "3600"]
            + ["--progress-every", "2", "--out", str(out)],
            stdout=stdout,
            stderr=stderr,
            env=env,
            stdin=subprocess.DEVNULL,
            # As from a terminal, where Ctrl-C interrupts it: a test run in the background
            # (a CI job, `make test &`) ignores SIGINT, and its children would inherit that.
            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL),
        )


def end_of_demo(demo, logs, timeout=120):
    """Wait for the main job to exit; its stderr. If it does not, kill it and fail with the
    end of what it printed."""
    try:
        demo.wait(timeout=timeout)
    except subprocess.TimeoutExpired:
        kill_tree(demo)  # and the roslaunch it started in a session of its own
        raise AssertionError(
            f"mapping_demo did not exit within {timeout} s:\n"
            + (logs / "stdout").read_text()[-3000:]
            + (logs / "stderr").read_text()[-3000:]
        ) from None
    return (logs / "stderr").read_text()


@pytest.mark.slow
@pytest.mark.timeout(300)
def test_demo_ends_naming_slam_gmapping_when_it_dies(tmp_path):
    """slam_gmapping is required: killed mid-run, the main job stops at once and says which
    node died, instead of exploring on without a map."""
    stdout = tmp_path / "stdout"
    demo = start_long_demo(tmp_path / "out", tmp_path)
    try:

        def slam_pid():
            if "s simulated" not in stdout.read_text():  # the simulation is under way
                return None
            pids = [p for p, cmd in descendants(demo.pid).items() if "__name:=slam_gmapping" in cmd]
            return pids[0] if pids else None

        wait_until(
            lambda: demo.poll() is not None or slam_pid() is not None,
            timeout=180,
            what="slam_gmapping under a running main job",
            interval=0.2,
        )
        assert demo.poll() is None, (tmp_path / "stderr").read_text()
        os.kill(slam_pid(), signal.SIGKILL)
        err = end_of_demo(demo, tmp_path)
    finally:
        if demo.poll() is None:
            kill_tree(demo)
    assert demo.returncode == 1, err
    assert "mapping_demo: slam_gmapping died, which ends the run" in err, err


@pytest.mark.slow
@pytest.mark.timeout(300)
def test_an_interrupted_run_keeps_the_earlier_runs_bag(tmp_path):
    """Ctrl-C half-way through a run into the --out of an earlier one: the earlier complete
    bag stays as it was (the run records to office.partial.bag and moves it into place
    only when it completes), and the output says so."""
    out = tmp_path / "out"
    out.mkdir()
    earlier = out / "office.bag"
    earlier.write_bytes(b"the earlier run's complete bag")
    stdout = tmp_path / "stdout"
    demo = start_long_demo(out, tmp_path)
    try:
        # Under way: the simulation runs and the recorder has its file open.
        wait_until(
            lambda: (
                demo.poll() is not None
                or (
                    "s simulated" in stdout.read_text()
                    and (out / "office.partial.bag.active").exists()
                )
            ),
            timeout=180,
            what="the run to be recording",
        )
        assert demo.poll() is None, (tmp_path / "stderr").read_text()
        demo.send_signal(signal.SIGINT)  # what Ctrl-C sends it (roslaunch has its own session)
        err = end_of_demo(demo, tmp_path)
    finally:
        if demo.poll() is None:
            kill_tree(demo)
    assert demo.returncode == 130, err
    assert earlier.read_bytes() == b"the earlier run's complete bag"
    assert (
        "mapping_demo: the run did not finish: office.bag from an earlier run is kept; this "
        "run's incomplete recording is office.partial.bag" in err
    ), err
    assert (out / "office.partial.bag").exists()
