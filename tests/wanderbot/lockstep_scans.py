#!/usr/bin/python3
"""Test helper (not a test): a lock-step /clock (tests/tools/lockstep_clock.py) gated on
`cmd_vel` that also publishes one synthetic LaserScan per tick on `scan`, following a
schedule PATTERN@SECONDS ... in sim seconds (patterns: fake_scan.py's). The scan for sim time
T goes out once the node has published at T, so the node drives on it from the next tick."""

import argparse
import sys
from pathlib import Path

import rospy
from sensor_msgs.msg import LaserScan

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parent / "tools"))
from fake_scan import parse_plan, scan_at  # noqa: E402
from lockstep_clock import Lockstep, input_publisher, run_program  # noqa: E402


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--out", required=True)
    parser.add_argument("--period", type=float, default=0.1)
    parser.add_argument("--ticks", type=int, required=True)
    parser.add_argument("plan", nargs="+", help="PATTERN@SECONDS")
    args = parser.parse_args(rospy.myargv()[1:])
    plan = parse_plan(args.plan)  # an unknown pattern fails here

    rospy.init_node("lockstep_scans", disable_signals=True)
    clock = Lockstep("cmd_vel", args.period, out=args.out)
    pub = input_publisher("scan", LaserScan)  # written before the next tick goes out
    clock.inputs = [pub]

    def on_tick(tick):
        now = tick * args.period
        secs, nsecs = divmod(clock.clock_ns, 1_000_000_000)
        # + 1e-9: a pattern planned at a tick's time is due at that tick despite rounding.
        scan = scan_at(plan, now + 1e-9, rospy.Time(secs, nsecs))
        pub.publish(scan)
        return 0

    return run_program(clock, args.ticks, on_tick, "lockstep_scans")


if __name__ == "__main__":
    sys.exit(main())
