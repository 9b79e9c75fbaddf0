// A planar pose (x, y, yaw) and its composition, the only geometry the filter needs.
#pragma once

#include <cmath>

namespace amcl_lite {

inline double wrapAngle(double a) { return std::atan2(std::sin(a), std::cos(a)); }

struct Pose2 {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;

  Pose2() = default;
  Pose2(double x_, double y_, double yaw_) : x(x_), y(y_), yaw(yaw_) {}

  // this * other: `other` expressed in this pose's frame, brought into the parent frame.
  Pose2 operator*(const Pose2& o) const {
    const double c = std::cos(yaw), s = std::sin(yaw);
    return Pose2(x + c * o.x - s * o.y, y + s * o.x + c * o.y, wrapAngle(yaw + o.yaw));
  }

  Pose2 inverse() const {
    const double c = std::cos(yaw), s = std::sin(yaw);
    return Pose2(-c * x - s * y, s * x - c * y, wrapAngle(-yaw));
  }
};

}  // namespace amcl_lite
