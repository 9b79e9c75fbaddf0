// LaserScan data to the library's beams and ranges, with the laser's mounting from tf.
#pragma once

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

// True when the laser's z axis points down in the base frame.
bool upsideDown(const tf2::Transform& laser_in_base);

// REP 117 ranges to the library's convention: NaN and readings below range_min (or -inf) are
// skipped (NaN); +inf and readings at or above range_max mean "no return" (+inf).
Ranges toRanges(const std::vector<float>& ranges, double range_min, double range_max);

}  // namespace gmapping_lite
