// Laser geometry in the robot base frame, and one scan's ranges.
//
// Beams are described by their direction in the base frame, so asymmetric scans, reversed
// beam order (an upside-down laser) and small tilts all reduce to the same table.
#pragma once

#include <vector>

#include "gmapping_lite/pose2.h"

namespace gmapping_lite {

struct Beam {
  double angle = 0.0;  // direction in the base frame (rad)
  double scale = 1.0;  // horizontal share of a range (cos of the beam's elevation)
};

struct LaserGeometry {
  Pose2 origin;  // laser centre in the base frame (theta unused: beams carry their angles)
  std::vector<Beam> beams;

  // A planar laser at `origin` with `count` beams from angle_min in steps of increment.
  static LaserGeometry planar(const Pose2& origin, double angle_min, double increment,
                              int count);
};

// Ranges in beam order. Conventions: NaN = no information (skipped), +inf = no return
// within range (clears free space up to maxUrange), finite = a return.
using Ranges = std::vector<float>;

}  // namespace gmapping_lite
