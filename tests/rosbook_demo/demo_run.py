"""The main job's short run, as both rosbook_demo tests start it: scripts/demo.sh for
SIM_SECONDS of exploration at speed 4, progress every 30 sim s, into `out`."""

import subprocess
from pathlib import Path

from roskit import ros_environment

REPO = Path(__file__).resolve().parents[2]
SIM_SECONDS = 120


def run_demo(out, extra_args=(), timeout=900):
    """Run demo.sh to its end; returns the CompletedProcess (text output)."""
    env = ros_environment(0)  # demo.sh picks its own master ports; this only checks the env
    env.pop("ROS_MASTER_URI")
    return subprocess.run(
        [str(REPO / "scripts" / "demo.sh")]
        + ["--sim-seconds", str(SIM_SECONDS), "--speed", "4", "--progress-every", "30"]
        + [*extra_args, "--out", str(out)],
        capture_output=True,
        text=True,
        timeout=timeout,
        env=env,
        stdin=subprocess.DEVNULL,
    )
