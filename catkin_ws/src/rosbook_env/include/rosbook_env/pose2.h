// A planar pose (x, y, theta) and its frame algebra: the one Pose2 of the C++ packages
// (gmapping_lite's SLAM, amcl_lite's localization). Header-only, no ROS inside, so the
// packages' ROS-free libraries can use it.
#pragma once

#include <cmath>

namespace rosbook_env {

// An angle brought into [-pi, pi).
inline double normalizeAngle(double a) {
  a = std::fmod(a + M_PI, 2.0 * M_PI);
  if (a < 0.0) a += 2.0 * M_PI;
  return a - M_PI;
}

struct Pose2 {
  double x = 0.0;
  double y = 0.0;
  double theta = 0.0;

  Pose2() = default;
  Pose2(double x_, double y_, double theta_) : x(x_), y(y_), theta(theta_) {}

  // this ⊕ d: `d` expressed in this pose's frame, brought into the parent frame (a motion
  // applied to this pose).
  Pose2 operator*(const Pose2& d) const {
    const double c = std::cos(theta), s = std::sin(theta);
    return {x + c * d.x - s * d.y, y + s * d.x + c * d.y, normalizeAngle(theta + d.theta)};
  }

  Pose2 inverse() const {
    const double c = std::cos(theta), s = std::sin(theta);
    return {-c * x - s * y, s * x - c * y, normalizeAngle(-theta)};
  }

  // The motion that takes `from` to this pose, in `from`'s frame (this = from ⊕ result).
  Pose2 relativeTo(const Pose2& from) const { return from.inverse() * (*this); }
};

}  // namespace rosbook_env
