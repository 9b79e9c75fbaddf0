#include "gmapping_lite/scan_input.h"

#include <cmath>
#include <limits>
#include <sstream>

namespace gmapping_lite {

bool upsideDown(const tf2::Transform& laser_in_base) {
  return (laser_in_base.getBasis() * tf2::Vector3(0, 0, 1)).z() < 0.0;
}

bool makeLaserGeometry(const tf2::Transform& laser_in_base, double angle_min,
                       double angle_increment, std::size_t count, double tilt_tolerance,
                       LaserGeometry* out, std::string* error) {
  const tf2::Matrix3x3& basis = laser_in_base.getBasis();
  const tf2::Vector3 normal = basis * tf2::Vector3(0, 0, 1);
  const double tilt = std::acos(std::min(1.0, std::fabs(normal.z())));
  if (tilt > tilt_tolerance) {
    std::ostringstream msg;
    msg << "the laser's scan plane is tilted " << tilt * 180.0 / M_PI
        << " degrees from the base's horizontal plane (tolerance "
        << tilt_tolerance * 180.0 / M_PI << " degrees); mount it level or raise ~tilt_tolerance";
    *error = msg.str();
    return false;
  }
  if (!std::isfinite(angle_min) || !std::isfinite(angle_increment) || count == 0) {
    *error = "the scan has no beams or non-finite angles";
    return false;
  }
  out->origin = Pose2(laser_in_base.getOrigin().x(), laser_in_base.getOrigin().y(), 0.0);
  out->beams.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double a = angle_min + double(i) * angle_increment;
    const tf2::Vector3 d = basis * tf2::Vector3(std::cos(a), std::sin(a), 0.0);
    out->beams[i].angle = std::atan2(d.y(), d.x());
    out->beams[i].scale = std::hypot(d.x(), d.y());
  }
  return true;
}

Ranges toRanges(const std::vector<float>& ranges, double range_min, double range_max) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  Ranges out(ranges.size());
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    const float r = ranges[i];
    if (std::isnan(r) || r < range_min) {
      out[i] = nan;
    } else if (r >= range_max) {
      out[i] = inf;
    } else {
      out[i] = r;
    }
  }
  return out;
}

}  // namespace gmapping_lite
