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

namespace {
// Angles are float32 in the message: a full-turn laser's -pi..pi rounds to 2 pi + 2e-7. Allow
// that rounding, not a second turn.
constexpr double kTurnTolerance = 1e-4;

std::string named(const char* field, double value, const char* rule) {
  std::ostringstream msg;
  msg << field << " is " << value << ": " << rule;
  return msg.str();
}
}  // namespace

std::optional<std::string> scanProblem(double angle_min, double angle_max, double angle_increment,
                                       std::size_t range_count, double range_min,
                                       double range_max) {
  if (!std::isfinite(angle_min)) return named("angle_min", angle_min, "it must be finite");
  if (!std::isfinite(angle_max)) return named("angle_max", angle_max, "it must be finite");
  if (!std::isfinite(angle_increment) || angle_increment == 0.0)
    return named("angle_increment", angle_increment,
                 "it must be a finite, non-zero angle between beams");
  if (!std::isfinite(range_min) || range_min < 0.0)
    return named("range_min", range_min, "it must be finite and >= 0");
  if (!std::isfinite(range_max) || range_max <= 0.0)
    return named("range_max", range_max, "it must be finite and > 0");
  std::ostringstream msg;
  if (range_min >= range_max) {
    msg << "range_min " << range_min << " is not below range_max " << range_max;
    return msg.str();
  }
  const double span = angle_max - angle_min;
  if (std::fabs(span) > 2.0 * M_PI + kTurnTolerance) {
    msg << "angle_min " << angle_min << " to angle_max " << angle_max << " spans "
        << std::fabs(span) << " rad: more than one full turn";
    return msg.str();
  }
  if (range_count == 0) return std::string("the scan has no ranges");
  if (span * angle_increment < 0.0) {
    msg << "angle_increment " << angle_increment << " has the opposite sign of angle_max - "
        << "angle_min (" << span << "): the beams run away from angle_max";
    return msg.str();
  }
  const double beams = span / angle_increment + 1.0;
  if (std::fabs(double(range_count) - beams) > kBeamCountTolerance) {
    msg << range_count << " ranges, but angle_min " << angle_min << " to angle_max " << angle_max
        << " in steps of angle_increment " << angle_increment << " make " << beams << " beams";
    return msg.str();
  }
  return std::nullopt;
}

bool ScanDrops::count(double stamp) {
  ++total_;
  const bool jumped_back = stamp < last_report_ - period_;
  if (reported_ && !jumped_back && stamp < last_report_ + period_) return false;
  reported_ = true;
  last_report_ = stamp;
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
