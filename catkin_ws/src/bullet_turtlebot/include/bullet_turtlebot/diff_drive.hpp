// Differential-drive kinematics with Kobuki limits: velocity ramps with acceleration limits
// and exact (arc) pose integration.
#pragma once

#include "bullet_turtlebot/types.hpp"

namespace bullet_turtlebot {

struct DriveLimits {
  double max_linear = 0.7;        // m/s, Kobuki
  double max_angular = 3.14;      // rad/s, Kobuki (180 deg/s)
  double accel_linear = 2.0;      // m/s^2
  double accel_angular = 6.0;     // rad/s^2
  double wheel_separation = 0.230;
  double wheel_radius = 0.035;
};

// Pose after moving at constant (v, w) for dt, along the exact arc.
Pose2D integrate_arc(const Pose2D& pose, double v, double w, double dt);

// Moves `current` towards `target` by at most accel * dt.
double ramp(double current, double target, double accel, double dt);

// Clamps a command to the limits (the command is assumed finite).
void clamp_command(const DriveLimits& limits, double* v, double* w);

}  // namespace bullet_turtlebot
