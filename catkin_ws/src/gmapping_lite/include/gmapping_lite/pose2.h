// A planar pose (x, y, yaw) and the frame algebra the filter needs.
#pragma once

#include <cmath>

namespace gmapping_lite {

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

  // this ⊕ d: apply a motion expressed in this pose's frame.
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

}  // namespace gmapping_lite
