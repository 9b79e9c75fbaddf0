"""Progress lines for long simulated runs: simulated time, speed-up, distance, map size."""

import math
import re

# A run that holds less than this share of the speed asked is reported: below it, the pauses
# the simulator makes for a lagging driver (~wait_for_commands) or the machine's load have
# taken a fifth of the time, which is when SLAM's live results start to differ from offline.
SPEED_HELD_SHARE = 0.8


class ProgressMeter:
    def __init__(self, sim_seconds, wall_start, sim_start):
        self.sim_seconds = sim_seconds
        self.wall_start = wall_start
        self.sim_start = sim_start
        self.distance = 0.0
        self._last_xy = None

    def add_position(self, x, y):
        if not (math.isfinite(x) and math.isfinite(y)):
            return
        if self._last_xy is not None:
            self.distance += math.hypot(x - self._last_xy[0], y - self._last_xy[1])
        self._last_xy = (x, y)

    def speed_held(self, sim_now, wall_now):
        """Simulated seconds per wall second since the start."""
        return max(sim_now - self.sim_start, 0.0) / max(wall_now - self.wall_start, 1e-9)

    def speed_warning(self, sim_now, wall_now, asked):
        """A warning when the run held clearly less than the speed asked (None otherwise): the
        machine was too busy, so the nodes saw the world slower than planned."""
        held = self.speed_held(sim_now, wall_now)
        if asked > 0 and held < SPEED_HELD_SHARE * asked:
            return (
                f"held only {held:.1f}x real time of the {asked:g}x asked: the machine was busy; "
                "a lower --speed gives SLAM and the explorer the time they were meant to have"
            )
        return None

    def line(self, sim_now, wall_now, known_area_m2=None):
        elapsed_sim = max(sim_now - self.sim_start, 0.0)
        elapsed_wall = max(wall_now - self.wall_start, 1e-9)
        fraction = min(elapsed_sim / self.sim_seconds, 1.0) if self.sim_seconds > 0 else 0.0
        bar = "#" * int(round(20 * fraction))
        parts = [
            f"[{bar:<20}] {elapsed_sim:6.0f}/{self.sim_seconds:.0f} s simulated",
            f"{elapsed_sim / elapsed_wall:5.1f}x real time",
            f"travelled {self.distance:6.1f} m",
        ]
        if known_area_m2 is not None:
            parts.append(f"map {known_area_m2:6.1f} m² known")
        return " | ".join(parts)


def known_area(grid):
    """Area (m²) of the cells of an OccupancyGrid that are not unknown (-1)."""
    known = sum(1 for v in grid.data if v != -1)
    return known * grid.info.resolution**2


# slam_gmapping's scan counts on /diagnostics (its "<node>: scans" status).
SLAM_SCANS_RECEIVED = "scans received"
SLAM_SCANS_SKIPPED = "scans skipped (fell behind)"


def slam_scan_counts(diagnostic_status):
    """{key: int} from slam_gmapping's scans status (a diagnostic_msgs/DiagnosticStatus), or
    None for any other status."""
    if not diagnostic_status.name.endswith(": scans"):
        return None
    counts = {}
    for kv in diagnostic_status.values:
        try:
            counts[kv.key] = int(kv.value)
        except ValueError:
            continue
    return counts if SLAM_SCANS_RECEIVED in counts and SLAM_SCANS_SKIPPED in counts else None


def slam_skip_warning(counts):
    """A warning when slam_gmapping skipped scans because it fell behind (None otherwise):
    it then mapped fewer scans than a run on the bag would, so the live map may be worse."""
    if not counts or counts[SLAM_SCANS_SKIPPED] <= 0:
        return None
    skipped, received = counts[SLAM_SCANS_SKIPPED], max(counts[SLAM_SCANS_RECEIVED], 1)
    return (
        f"slam_gmapping fell behind and skipped {skipped} of {received} scans "
        f"({skipped / received:.0%}); a lower --speed lets it map every scan"
    )


# roslaunch's line when a node marked required="true" ends: "REQUIRED process [slam_gmapping-3]
# has died!" (the number is roslaunch's own count of the processes it started).
_REQUIRED_DIED = re.compile(r"REQUIRED process \[(.+?)(?:-\d+)?\] has died")
_ANY_DIED = re.compile(r"\[([^\[\]\s]+?)(?:-\d+)?\] process has died")


def died_nodes(launch_log, required_only=True):
    """The required nodes (or, with required_only=False, any nodes) roslaunch reports dead
    in its output, in order, without repeats."""
    names = []
    found = _REQUIRED_DIED.findall(launch_log)
    if not required_only:
        found += _ANY_DIED.findall(launch_log)
    for name in found:
        if name not in names:
            names.append(name)
    return names
