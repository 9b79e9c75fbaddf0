"""The exploring behaviour, free of ROS: look around, go to the chosen frontier, look at
it, repeat; recover when stuck; stop when no reachable frontier is left.

The owner calls `control()` at a fixed rate with the robot pose and the free distance
ahead, calls `wants_plan()` with the stamp of its latest map to learn when to run the
planner (with the arguments `plan_inputs()` gives), and hands the result (a
map_planner.Plan or None) to `accept_plan()`. Every time is in seconds of ROS time.

It never gives up early. A frontier looked at in vain from afar (`max_visits` times) is
approached closely next; one looked at in vain closely too is set aside, and so is a goal
the robot failed to reach (for `blacklist_timeout`). When nothing but set-aside frontiers
and goals is left, all of them are retried; `done` comes only when no frontier can be
planned for, or when a round of retries revealed nothing (less known free area gained than
`min_progress`), so the retries cannot go on forever.

SLAM publishes its map every few seconds, so right after looking at a frontier the map
does not show what was just seen. Rather than wait, the explorer remembers where it
looked (`pending_views`) and the planner treats the frontier cells seen from there as
observed until a newer map arrives."""

import math
from dataclasses import dataclass

from .follower import FollowerParams, PurePursuit, turn_towards, wrap
from .recovery import Blacklist, Recovery, RecoveryParams, StuckMonitor

SPIN, WAIT, FOLLOW, LOOK, RECOVER, DONE = "spin", "wait", "follow", "look", "recover", "done"


@dataclass
class ExplorerParams:
    replan_period: float = 3.0  # s: replan at most this often while following
    stop_distance: float = 0.40  # m from the robot centre: no forward motion closer
    slow_gain: float = 1.0  # forward speed limit per metre of clearance beyond stop_distance
    spin_speed: float = 0.8  # rad/s for the initial look around
    initial_spin: float = 2 * math.pi  # rad to turn before the first plan (0: none)
    blacklist_timeout: float = 60.0  # s
    goal_timeout_factor: float = 3.0  # give up a goal after this x its expected time
    goal_timeout_min: float = 20.0  # s
    done_after: int = 2  # consecutive plans without a frontier before declaring done
    # Looks at the same frontier (in blacklist_timeout) before escalating. One: a look
    # sweeps its frontier and map_angular_update beyond both ends (see map_planner), so
    # every part of it reaches the map; another look from a like place sees the same.
    max_visits: int = 1


class Explorer:
    def __init__(
        self, params=None, follower=None, recovery=None, blacklist_radius=0.8, min_progress=1.0
    ):
        """`min_progress` (m^2): a round of retries that made less known free area than
        this revealed nothing; the owner passes the planner's min_gain (a frontier opening
        onto less unknown space is not worth a visit either)."""
        self.params = params or ExplorerParams()
        self.follower_params = follower or FollowerParams()
        self.recovery_params = recovery or RecoveryParams()
        self.min_progress = min_progress
        self.blacklist = Blacklist(blacklist_radius, self.params.blacklist_timeout)
        # Frontiers looked at from afar again and again in vain (a grazing view along a
        # shadow, an occluded corner): approached closely from then on.
        self.close_targets = Blacklist(blacklist_radius, math.inf)
        # Frontiers looked at in vain closely too: set aside until nothing else is left.
        self.dead_frontiers = Blacklist(blacklist_radius, math.inf)
        self.retry_area = None  # known free area (m^2) when the last retry round began
        self.retry_rounds = 0
        self.stuck = StuckMonitor()
        self.state = SPIN
        self.spun = 0.0
        self.last_yaw = None
        self.follower = None
        self.plan = None
        self.goal_started = 0.0
        self.goal_deadline = math.inf  # give up the goal (blacklist it) after this time
        self.last_plan_time = -math.inf
        self.plan_requested = False
        self.recovery = None
        self.recover_count = 0
        self.empty_plans = 0
        self.events = []  # human-readable progress messages for the owner to log
        self.goals_reached = 0
        self.planned_stamp = -math.inf  # stamp of the map the last plan used
        self.views = []  # (x, y, yaw, time) where the robot looked at a frontier
        self.reached = []  # (x, y, time, close) of looked-at targets, to catch repeats
        self.look_queue = []  # headings still to turn through at the goal
        if self.params.initial_spin <= 0:
            self._request_plan(WAIT)

    # -- planning ----------------------------------------------------------------
    @property
    def done(self):
        return self.state == DONE

    @property
    def current_goal(self):
        return self.plan.goal if self.plan is not None and self.state == FOLLOW else None

    def wants_plan(self, now, map_stamp):
        """Whether to plan now; `map_stamp` is the latest map's stamp (None: no map)."""
        if map_stamp is None or self.state in (SPIN, LOOK, RECOVER):
            return False
        map_is_new = map_stamp > self.planned_stamp
        if self.plan_requested:
            return True
        if self.state == WAIT:
            # SLAM publishes only after the robot moved or turned enough: do not wait
            # forever for a new map while standing still.
            return map_is_new or now - self.last_plan_time >= self.params.replan_period
        return map_is_new and now - self.last_plan_time >= self.params.replan_period

    def excluded_points(self, now):
        return self.blacklist.active(now)

    def excluded_frontiers(self, now):
        return self.dead_frontiers.active(now)

    def plan_inputs(self, now, map_stamp):
        """Keyword arguments for map_planner.MapPlanner.plan (besides the robot's x, y)."""
        return {
            "excluded_points": self.excluded_points(now),
            "current_goal": self.current_goal,
            "views": self.pending_views(map_stamp),
            "dead_frontiers": self.excluded_frontiers(now),
            "close_targets": self.close_targets.active(now),
        }

    def pending_views(self, map_stamp):
        """Views (x, y, yaw) taken after the map was made: the map does not show them."""
        self.views = [v for v in self.views if v[3] > map_stamp]
        return [v[:3] for v in self.views]

    def accept_plan(self, plan, now, map_stamp, known_area=None, start_blocked=False):
        """`known_area`: m^2 of known free space on the planned map (None: not known, and
        then one round of retries at most); `start_blocked`: the planner found no
        traversable cell near the robot, so None says nothing about frontiers."""
        self.last_plan_time = now
        self.planned_stamp = map_stamp
        self.plan_requested = False
        if plan is None and start_blocked and self.state != DONE:
            # Not the goal's fault: recover without blacklisting it.
            self.follower = None
            self.state = WAIT
            self._recover(now, "no traversable cell near the robot")
            return
        if plan is None:
            if self.views:
                # The map is older than our last looks, and what we looked at hides every
                # frontier left on it. Turn around once: SLAM updates its map when the
                # robot turns, and the turn may reveal more.
                self.views = []
                self._start_spin()
                return
            self._no_frontier(now, known_area)
            return
        self.empty_plans = 0
        if self.state == DONE:
            self.events.append("new frontier found: exploring again")
        if not plan.kept or self.state != FOLLOW:
            self.events.append(
                f"goal ({plan.goal[0]:.2f}, {plan.goal[1]:.2f}): path {plan.cost:.1f} m, "
                f"frontier {plan.frontier_size:.1f} m opening onto {plan.gain:.1f} m^2, "
                f"{plan.frontiers_left} frontiers left{', close approach' if plan.close else ''}"
            )
            self.goal_started = now
            # From the whole path's expected time, fixed for the goal: a kept plan's path
            # is only what is left of it, and measured against the time since the start
            # it gave up every long goal shortly before the robot got there.
            expected = plan.cost / max(self.follower_params.max_linear, 1e-3)
            p = self.params
            self.goal_deadline = now + max(p.goal_timeout_min, p.goal_timeout_factor * expected)
            self.stuck.reset()
        self.plan = plan
        self.follower = PurePursuit(plan.path, self.follower_params)
        self.state = FOLLOW

    def _no_frontier(self, now, known_area=None):
        if self.state == FOLLOW:
            # Our frontier was explored on the way and nothing else is reachable: stop
            # and ask again; the map may still be catching up.
            self.follower = None
        goals = len(self.blacklist.active(now))
        frontiers = len(self.dead_frontiers.active(now))
        if (goals or frontiers) and self._retry_worthwhile(known_area):
            self.retry_rounds += 1
            self.events.append(
                f"no frontier left but {goals} blacklisted goals and {frontiers} frontiers "
                f"set aside: retrying them (round {self.retry_rounds})"
            )
            self.blacklist.clear()
            for x, y in self.dead_frontiers.active(now):
                self._approach_closely(x, y, now)
            self.dead_frontiers.clear()
            self.reached = []
            self.retry_area = known_area
            self.empty_plans = 0
            self._request_plan(WAIT)
            return
        self.empty_plans += 1
        if self.empty_plans >= self.params.done_after:
            if self.state != DONE:
                why = "no reachable frontier left"
                if goals or frontiers:
                    why = (
                        f"{goals} goals and {frontiers} frontiers still set aside, but the "
                        "last round of retries revealed nothing"
                    )
                self.events.append(f"exploration done: {why}")
            self.state = DONE
        else:
            self.state = WAIT

    def _retry_worthwhile(self, known_area):
        """A first round of retries always; another only if the last one revealed at
        least min_progress m^2 (without the area, never)."""
        if self.retry_rounds == 0:
            return True
        if known_area is None or self.retry_area is None:
            return False
        return known_area - self.retry_area >= self.min_progress

    # -- control -----------------------------------------------------------------
    def control(self, now, x, y, yaw, clearance=math.inf):
        """(linear, angular) for this cycle."""
        if self.state == SPIN:
            return self._spin(yaw)
        if self.state == FOLLOW:
            return self._follow(now, x, y, yaw, clearance)
        if self.state == LOOK:
            return self._look(now, x, y, yaw)
        if self.state == RECOVER:
            linear, angular, finished = self.recovery.command(now)
            if finished:
                self._request_plan(WAIT)
            return linear, angular
        return 0.0, 0.0

    def _start_spin(self):
        self.state = SPIN
        self.spun = 0.0
        self.last_yaw = None

    def _spin(self, yaw):
        if self.last_yaw is not None:
            self.spun += abs(wrap(yaw - self.last_yaw))
        self.last_yaw = yaw
        if self.spun >= (self.params.initial_spin or 2 * math.pi):
            self._request_plan(WAIT)
            return 0.0, 0.0
        return 0.0, self.params.spin_speed

    def _look(self, now, x, y, yaw):
        """Turn through the queued headings, noting each view; then ask for a plan."""
        while self.look_queue:
            # Through the headings before the last at full rate: a sweep need not stop
            # at each of them (the scans go on as it turns).
            passing = len(self.look_queue) > 1
            angular, finished = turn_towards(
                yaw, self.look_queue[0], self.follower_params, passing=passing
            )
            if not finished:
                return 0.0, angular
            self.views.append((x, y, yaw, now))
            self.look_queue.pop(0)
        self._request_plan(WAIT)
        return 0.0, 0.0

    def _arrived(self, now):
        gx, gy = self.plan.goal
        tx, ty = self.plan.target
        # A frontier already to be approached closely counts as such even when the planner
        # found no goal on it and looked from afar again.
        radius = self.dead_frontiers.radius
        close = self.plan.close or any(
            math.hypot(cx - tx, cy - ty) < radius for cx, cy in self.close_targets.active(now)
        )
        self.goals_reached += 1
        self.events.append(f"reached goal ({gx:.2f}, {gy:.2f})")
        timeout = self.params.blacklist_timeout
        self.reached = [r for r in self.reached if now - r[2] < timeout]
        visits = sum(
            math.hypot(rx - tx, ry - ty) < radius and was_close == close
            for rx, ry, _, was_close in self.reached
        )
        if visits >= self.params.max_visits - 1:
            # Looked at this part of a frontier before, and it is still there.
            if close:
                # Even from close by: it cannot be mapped from where we can go (too low,
                # occluded, too far). Set aside until nothing else is left.
                self.events.append(
                    f"frontier at ({tx:.2f}, {ty:.2f}) looked at {visits + 1} times closely: "
                    "set aside"
                )
                self._set_aside(tx, ty, now)
            else:
                # From afar the view may graze along a shadow's edge: go up to it.
                self.events.append(
                    f"frontier at ({tx:.2f}, {ty:.2f}) looked at {visits + 1} times: "
                    "approaching it closely"
                )
                self._approach_closely(tx, ty, now)
        self.reached.append((tx, ty, now, close))

    def _set_aside(self, tx, ty, now):
        """Set aside the frontier cells this goal was chosen for: around each of them, not
        only around their mean (the target), which may lie blacklist_radius from all of
        them when they are spread out; then the planner would choose them again and again."""
        points = getattr(self.plan, "seen_points", None)
        if points is None or not len(points):
            points = [(tx, ty)]
        radius = self.dead_frontiers.radius
        active = self.dead_frontiers.active(now)
        for x, y in points:
            # One entry per blacklist_radius is enough.
            if all(math.hypot(x - dx, y - dy) >= radius / 2 for dx, dy in active):
                self.dead_frontiers.add(float(x), float(y), now)
                active.append((x, y))

    def _approach_closely(self, x, y, now):
        radius = self.close_targets.radius
        if all(math.hypot(x - cx, y - cy) >= radius for cx, cy in self.close_targets.active(now)):
            self.close_targets.add(x, y, now)

    def _request_plan(self, state):
        self.state = state
        self.plan_requested = True
        self.stuck.reset()

    def _follow(self, now, x, y, yaw, clearance):
        p = self.params
        room = max(0.0, clearance - p.stop_distance) * p.slow_gain
        linear, angular, arrived = self.follower.command(x, y, yaw, room)
        if arrived:
            self._arrived(now)
            headings = list(self.plan.look_yaws)
            if headings and abs(wrap(headings[-1] - yaw)) < abs(wrap(headings[0] - yaw)):
                headings.reverse()  # start the sweep at the nearer end
            self.look_queue = headings
            self.state = LOOK
            return self._look(now, x, y, yaw)
        if now > self.goal_deadline:
            self.events.append(f"goal timed out after {now - self.goal_started:.0f} s: blacklisted")
            self.blacklist.add(*self.plan.goal, now)
            self._request_plan(WAIT)
            return 0.0, 0.0
        if self.stuck.update(now, x, y, yaw):
            self._recover(now, "stuck")
            return self.recovery.command(now)[:2]
        return linear, angular

    def bumped(self, now):
        """A bumper was pressed: back off at once (the scan misses what is very close,
        low or beside the robot), and give up the goal that led there."""
        if self.state in (RECOVER, DONE):
            return
        self._recover(now, "bumper pressed")

    def _recover(self, now, why):
        self.recover_count += 1
        if self.plan is not None and self.state == FOLLOW:
            self.events.append(f"{why}: backing up, turning, blacklisting the goal")
            self.blacklist.add(*self.plan.goal, now)
        else:
            self.events.append(f"{why}: backing up, turning")
        sign = 1.0 if self.recover_count % 2 else -1.0
        self.recovery = Recovery(now, sign, self.recovery_params)
        self.state = RECOVER
        self.stuck.reset()
