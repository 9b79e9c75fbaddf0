#include "bullet_turtlebot/diff_drive.hpp"

#include <algorithm>
#include <cmath>

namespace bullet_turtlebot {

Pose2D integrate_arc(const Pose2D& pose, double v, double w, double dt) {
  Pose2D out = pose;
  const double dtheta = w * dt;
  if (std::abs(dtheta) < 1e-9) {
    // Straight line (second-order in the tiny rotation).
    const double heading = pose.yaw + dtheta / 2;
    out.x += v * dt * std::cos(heading);
    out.y += v * dt * std::sin(heading);
  } else {
    const double r = v / w;
    out.x += r * (std::sin(pose.yaw + dtheta) - std::sin(pose.yaw));
    out.y += -r * (std::cos(pose.yaw + dtheta) - std::cos(pose.yaw));
  }
  out.yaw = normalize_angle(pose.yaw + dtheta);
  return out;
}

double ramp(double current, double target, double accel, double dt) {
  const double step = accel * dt;
  return current + std::clamp(target - current, -step, step);
}

void clamp_command(const DriveLimits& limits, double* v, double* w) {
  *v = std::clamp(*v, -limits.max_linear, limits.max_linear);
  *w = std::clamp(*w, -limits.max_angular, limits.max_angular);
}

}  // namespace bullet_turtlebot
