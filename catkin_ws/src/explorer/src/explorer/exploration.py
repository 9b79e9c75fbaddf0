"""The exploring behaviour, free of ROS: look around, go to the chosen frontier, look at
it, repeat; recover when stuck; stop when no reachable frontier is left.

The owner calls `control()` at a fixed rate with the robot pose and the free distance
ahead, calls `wants_plan()` to learn when to run the planner, and hands the result (a
map_planner.Plan or None) to `accept_plan()`. Every time is in seconds of ROS time."""

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
    blacklist_timeout: float = 60.0  # s
    goal_timeout_factor: float = 3.0  # give up a goal after this x its expected time
    goal_timeout_min: float = 20.0  # s
    done_after: int = 2  # consecutive plans without a frontier before declaring done


class Explorer:
    def __init__(self, params=None, follower=None, recovery=None, blacklist_radius=0.5):
        self.params = params or ExplorerParams()
        self.follower_params = follower or FollowerParams()
        self.recovery_params = recovery or RecoveryParams()
        self.blacklist = Blacklist(blacklist_radius, self.params.blacklist_timeout)
        self.stuck = StuckMonitor()
        self.state = SPIN
        self.spun = 0.0
        self.last_yaw = None
        self.follower = None
        self.plan = None
        self.goal_started = 0.0
        self.last_plan_time = -math.inf
        self.plan_requested = False
        self.recovery = None
        self.recover_count = 0
        self.empty_plans = 0
        self.events = []  # human-readable progress messages for the owner to log
        self.goals_reached = 0

    # -- planning ----------------------------------------------------------------
    @property
    def done(self):
        return self.state == DONE

    @property
    def current_goal(self):
        return self.plan.goal if self.plan is not None and self.state == FOLLOW else None

    def wants_plan(self, now, map_is_new):
        if self.state in (SPIN, LOOK, RECOVER):
            return False
        if self.state == WAIT or self.plan_requested:
            return map_is_new or now - self.last_plan_time >= self.params.replan_period
        return map_is_new and now - self.last_plan_time >= self.params.replan_period

    def excluded_points(self, now):
        return self.blacklist.active(now)

    def accept_plan(self, plan, now):
        self.last_plan_time = now
        self.plan_requested = False
        if plan is None:
            self._no_frontier(now)
            return
        self.empty_plans = 0
        if self.state == DONE:
            self.events.append("new frontier found: exploring again")
        if not plan.kept or self.state != FOLLOW:
            self.events.append(
                f"goal ({plan.goal[0]:.2f}, {plan.goal[1]:.2f}): path {plan.cost:.1f} m, "
                f"frontier {plan.frontier_size:.1f} m opening onto {plan.gain:.1f} m^2, "
                f"{plan.frontiers_left} frontiers left"
            )
            self.goal_started = now
            self.stuck.reset()
        self.plan = plan
        self.follower = PurePursuit(plan.path, self.follower_params)
        self.state = FOLLOW

    def _no_frontier(self, now):
        if self.state == FOLLOW:
            # Our frontier was explored on the way and nothing else is reachable: stop
            # and ask again; the map may still be catching up.
            self.follower = None
        self.empty_plans += 1
        if self.blacklist.active(now):
            self.events.append("no frontier left but blacklisted goals: retrying them")
            self.blacklist.clear()
            self.state = WAIT
            return
        if self.empty_plans >= self.params.done_after:
            if self.state != DONE:
                self.events.append("exploration done: no reachable frontier left")
            self.state = DONE
        else:
            self.state = WAIT

    # -- control -----------------------------------------------------------------
    def control(self, now, x, y, yaw, clearance=math.inf):
        """(linear, angular) for this cycle."""
        if self.state == SPIN:
            return self._spin(yaw)
        if self.state == FOLLOW:
            return self._follow(now, x, y, yaw, clearance)
        if self.state == LOOK:
            angular, finished = turn_towards(yaw, self.plan.look_yaw, self.follower_params)
            if finished:
                self.blacklist.add(*self.plan.goal, now)
                self._request_plan(WAIT)
            return 0.0, angular
        if self.state == RECOVER:
            linear, angular, finished = self.recovery.command(now)
            if finished:
                self._request_plan(WAIT)
            return linear, angular
        return 0.0, 0.0

    def _spin(self, yaw):
        if self.last_yaw is not None:
            self.spun += abs(wrap(yaw - self.last_yaw))
        self.last_yaw = yaw
        if self.spun >= 2 * math.pi:
            self._request_plan(WAIT)
            return 0.0, 0.0
        return 0.0, self.params.spin_speed

    def _request_plan(self, state):
        self.state = state
        self.plan_requested = True
        self.stuck.reset()

    def _follow(self, now, x, y, yaw, clearance):
        p = self.params
        room = max(0.0, clearance - p.stop_distance) * p.slow_gain
        linear, angular, arrived = self.follower.command(x, y, yaw, room)
        if arrived:
            self.goals_reached += 1
            self.events.append(f"reached goal ({self.plan.goal[0]:.2f}, {self.plan.goal[1]:.2f})")
            self.state = LOOK
            return 0.0, 0.0
        expected = self.plan.cost / max(self.follower_params.max_linear, 1e-3)
        limit = max(p.goal_timeout_min, p.goal_timeout_factor * expected)
        if now - self.goal_started > limit:
            self.events.append(f"goal timed out after {now - self.goal_started:.0f} s: blacklisted")
            self.blacklist.add(*self.plan.goal, now)
            self._request_plan(WAIT)
            return 0.0, 0.0
        if self.stuck.update(now, x, y, yaw):
            self.recover_count += 1
            self.events.append("stuck: backing up, turning, blacklisting the goal")
            self.blacklist.add(*self.plan.goal, now)
            sign = 1.0 if self.recover_count % 2 else -1.0
            self.recovery = Recovery(now, sign, self.recovery_params)
            self.state = RECOVER
            self.stuck.reset()
            return self.recovery.command(now)[:2]
        return linear, angular
