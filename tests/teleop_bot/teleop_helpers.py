"""Shared bits of the teleop_bot integration tests."""

import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
SEND_KEYS = ["/usr/bin/python3", str(HERE / "send_keys.py")]
sys.path.insert(0, str(HERE.parent / "tools"))
import lockstep  # noqa: E402, F401  (re-exported for the tests)


def twists(messages):
    """(ros time, linear x, angular z) per recorded Twist."""
    return [(m["ros"], m["msg"]["linear"]["x"], m["msg"]["angular"]["z"]) for m in messages]


def clock_twists(records):
    """(sim time, linear x, angular z) per Twist a lock-step clock recorded (lockstep.py)."""
    return [(r["clock"], r["msg"]["linear"]["x"], r["msg"]["angular"]["z"]) for r in records]


def ticks_between(records, first, last):
    """How many messages arrived at ticks first..last of a lock-step clock."""
    return sum(1 for r in records if first <= r["tick"] <= last)


def start_in_terminal(ros, cmd, name):
    """Start `cmd` with a fresh pseudo-terminal as its controlling terminal and stdin (as if
    typed in a terminal window); returns (proc, master fd, slave fd). Output goes to the
    graph's log file. Writing b"\\x03" to the master is a real Ctrl-C."""
    import fcntl
    import os
    import subprocess
    import termios

    master, slave = os.openpty()
    ros._log_index += 1
    log_path = ros.workdir / f"{ros._log_index:02d}-{name}.log"
    log = open(log_path, "w")

    def take_terminal():
        fcntl.ioctl(0, termios.TIOCSCTTY, 0)

    proc = subprocess.Popen(
        cmd,
        stdin=slave,
        stdout=log,
        stderr=subprocess.STDOUT,
        env=ros.env,
        cwd=ros.workdir,
        start_new_session=True,
        preexec_fn=take_terminal,
    )
    proc.log_path, proc.label = log_path, name
    ros.procs.append(proc)
    return proc, master, slave
