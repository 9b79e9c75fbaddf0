// LaserScan data to the library's beams and ranges, with the laser's mounting from tf.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <tf2/LinearMath/Transform.h>

#include "gmapping_lite/laser.h"

namespace gmapping_lite {

// Beams of a scan given the laser's pose in the base frame. Any mounting works whose scan
// plane is within `tilt_tolerance` (rad) of horizontal, upside down included (the beams then
// turn the other way). Returns false with a message otherwise.
bool makeLaserGeometry(const tf2::Transform& laser_in_base, double angle_min,
                       double angle_increment, std::size_t count, double tilt_tolerance,
                       LaserGeometry* out, std::string* error);

// Why a LaserScan's layout cannot be used, as one line naming the field, its value and the
// rule; nullopt when it can. Checked: angle_min / angle_max finite; angle_increment finite
// and non-zero; range_min / range_max finite, range_min >= 0 and below range_max; the scan
// spans at most one full turn; and `range_count` matches the angles,
// (angle_max - angle_min) / angle_increment + 1, within kBeamCountTolerance beams.
std::optional<std::string> scanProblem(double angle_min, double angle_max, double angle_increment,
                                       std::size_t range_count, double range_min,
                                       double range_max);

// Drivers round angle_max to the nearest float or compute it as angle_min + count *
// increment (one beam too far): anything within 1.5 beams is rounding, not a wrong layout.
constexpr double kBeamCountTolerance = 1.5;

// Counts scans dropped as malformed and says when to warn: the first at once, then at most
// once every `period` seconds of scan time (the dropped scans' stamps: the node's clock may
// not have started when the first scan arrives, and a bag has no other); stamps that jump back
// by more than a period (a bag played again) warn at once. A flood of bad scans gives a few
// lines, each with the running count, and never stops the good ones.
class ScanDrops {
 public:
  explicit ScanDrops(double period) : period_(period) {}
  // Count one dropped scan stamped `stamp` (s); true when this drop should be reported.
  bool count(double stamp);
  int total() const { return total_; }

 private:
  double period_;
  double last_report_ = 0.0;
  bool reported_ = false;
  int total_ = 0;
};

// True when the laser's z axis points down in the base frame.
bool upsideDown(const tf2::Transform& laser_in_base);

// REP 117 ranges to the library's convention: NaN and readings below range_min (or -inf) are
// skipped (NaN); +inf and readings at or above range_max mean "no return" (+inf).
Ranges toRanges(const std::vector<float>& ranges, double range_min, double range_max);

}  // namespace gmapping_lite
