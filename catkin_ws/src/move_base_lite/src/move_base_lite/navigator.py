"""One navigation goal, free of ROS: plan, follow the path (explorer.follower), stop for
what the scan sees, replan when the path is blocked, recover when stuck
(explorer.recovery), turn to the goal's heading, and end SUCCEEDED or ABORTED with a
reason. The owner calls `step()` at the controller rate with sim time and the robot pose,
and passes a `plan(start_xy, goal_xy)` function returning a global_planner.PlanResult."""

import math
from dataclasses import dataclass

from explorer.follower import FollowerParams, PurePursuit, turn_towards, wrap
from explorer.recovery import Recovery, RecoveryParams, StuckMonitor

ACTIVE, SUCCEEDED, ABORTED = "active", "succeeded", "aborted"
FOLLOW, ALIGN, RECOVER = "follow", "align", "recover"


@dataclass
class NavigatorParams:
    xy_goal_tolerance: float = 0.10  # m (base_local_planner's default)
    yaw_goal_tolerance: float = 0.10  # rad
    replan_period: float = 2.0  # s: replan this often (amcl's corrections move the robot)
    blocked_lookahead: float = 2.0  # m of path ahead checked against new obstacles
    # No forward motion closer than this to what the scan sees ahead (robot radius 0.18 m
    # plus the Kobuki's stopping distance at 0.5 m/s and 2 m/s^2, about 0.06 m, plus margin).
    stop_distance: float = 0.35
    slow_gain: float = 1.0  # m/s of forward speed per metre of room beyond stop_distance
    max_recoveries: int = 3  # stuck or planless episodes before aborting
    plan_retries: int = 2  # failed plans (with a recovery between) before aborting


@dataclass
class Command:
    linear: float
    angular: float


class Navigator:
    def __init__(self, goal, params=None, follower=None, recovery=None):
        """`goal`: (x, y, yaw) in the planning frame."""
        self.goal = goal
        self.params = params or NavigatorParams()
        self.follower_params = follower or FollowerParams()
        self.follower_params.goal_tolerance = self.params.xy_goal_tolerance
        self.recovery_params = recovery or RecoveryParams()
        self.status = ACTIVE
        self.text = ""
        self.mode = FOLLOW
        self.path = None
        self.pursuit = None
        self.last_plan = -math.inf
        self.failed_plans = 0
        self.recoveries = 0
        self.recovery = None
        self.stuck = StuckMonitor()
        self.events = []  # progress messages for the owner to log
        if not all(math.isfinite(v) for v in goal):
            # A NaN yaw would never be within the yaw tolerance: the robot would turn on
            # the spot for ever and the goal never end.
            self._abort(f"the goal ({', '.join(f'{v:g}' for v in goal)}) is not finite")

    def step(self, now, pose, clearance, plan, blocked=None):
        """Command for this cycle. `clearance`: free distance (m) ahead of the robot's
        centre; `blocked(path, xy)`: whether new obstacles cut the path ahead."""
        if self.status != ACTIVE:
            return Command(0.0, 0.0)
        x, y, yaw = pose
        if self.mode == RECOVER:
            linear, angular, finished = self.recovery.command(now)
            if not finished:
                return Command(linear, angular)
            self.mode = FOLLOW
            self.last_plan = -math.inf
            self.stuck.reset()
        if self.mode == ALIGN or math.hypot(self.goal[0] - x, self.goal[1] - y) <= (
            self.params.xy_goal_tolerance
        ):
            return self._align(yaw)
        is_blocked = blocked is not None and self.path is not None and blocked(self.path, (x, y))
        if is_blocked:
            self.events.append("path blocked by an obstacle the map lacks: replanning")
        if is_blocked or now - self.last_plan >= self.params.replan_period:
            command = self._replan(now, x, y, plan)
            if command is not None:
                return command
        room = max(0.0, clearance - self.params.stop_distance) * self.params.slow_gain
        linear, angular, arrived = self.pursuit.command(x, y, yaw, room)
        if arrived:
            return self._align(yaw)
        if self.stuck.update(now, x, y, yaw):
            return self._recover(now, "no progress")
        return Command(linear, angular)

    def _replan(self, now, x, y, plan):
        self.last_plan = now
        result = plan((x, y), self.goal[:2])
        if result.path is not None:
            self.failed_plans = 0
            self.path = result.path
            self.pursuit = PurePursuit(result.path, self.follower_params)
            return None
        self.failed_plans += 1
        if result.goal_invalid or self.failed_plans > self.params.plan_retries:
            return self._abort(f"no plan: {result.reason}")
        return self._recover(now, f"planning failed ({result.reason})")

    def _align(self, yaw):
        self.mode = ALIGN
        angular, done = turn_towards(
            yaw, self.goal[2], self.follower_params, self.params.yaw_goal_tolerance
        )
        if done:
            self.status = SUCCEEDED
            self.text = "goal reached"
            return Command(0.0, 0.0)
        return Command(0.0, angular)

    def _recover(self, now, why):
        self.recoveries += 1
        if self.recoveries > self.params.max_recoveries:
            return self._abort(f"{why} after {self.params.max_recoveries} recovery attempts")
        self.events.append(f"{why}: recovery {self.recoveries} (back up, turn)")
        sign = 1.0 if self.recoveries % 2 else -1.0
        self.recovery = Recovery(now, sign, self.recovery_params)
        self.mode = RECOVER
        self.stuck.reset()
        linear, angular, _ = self.recovery.command(now)
        return Command(linear, angular)

    def _abort(self, why):
        self.status = ABORTED
        self.text = why
        self.events.append(f"aborted: {why}")
        return Command(0.0, 0.0)


def heading_error(yaw, goal_yaw):
    return abs(wrap(goal_yaw - yaw))
