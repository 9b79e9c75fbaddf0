// A small asymmetric test world and a ray caster standing in for the Kinect's fake laser.
#pragma once

#include <cmath>
#include <vector>

#include "amcl_lite/likelihood_field.h"
#include "amcl_lite/particle_filter.h"

namespace amcl_lite_test {

// 8 m x 6 m room at 0.05 m with walls round it, an L-shaped wall and a pillar, so that no
// two places look alike.
inline amcl_lite::GridMap room() {
  amcl_lite::GridMap m;
  m.resolution = 0.05;
  m.origin_x = -1.0;
  m.origin_y = -2.0;
  m.width = 160;
  m.height = 120;
  m.cells.assign(m.width * m.height, 0);
  auto wall = [&](int r0, int c0, int r1, int c1) {
    for (int r = r0; r < r1; ++r)
      for (int c = c0; c < c1; ++c) m.cells[r * m.width + c] = 100;
  };
  wall(0, 0, 2, 160);
  wall(118, 0, 120, 160);
  wall(0, 0, 120, 2);
  wall(0, 158, 120, 160);
  wall(40, 60, 42, 120);   // L: horizontal arm
  wall(40, 118, 90, 120);  // L: vertical arm
  wall(80, 30, 88, 38);    // pillar
  return m;
}

inline double castRay(const amcl_lite::GridMap& m, double x, double y, double angle, double max_range) {
  const double step = m.resolution / 4.0;
  for (double r = 0.0; r < max_range; r += step) {
    const int c = static_cast<int>(std::floor((x + r * std::cos(angle) - m.origin_x) / m.resolution));
    const int row = static_cast<int>(std::floor((y + r * std::sin(angle) - m.origin_y) / m.resolution));
    if (c < 0 || row < 0 || c >= m.width || row >= m.height) return max_range;
    if (m.cells[row * m.width + c] >= 65) return r;
  }
  return max_range;
}

// A 58-degree, 640-reading scan from a laser at `pose` (the Kinect's fake laser).
inline amcl_lite::ScanObservation kinectScan(const amcl_lite::GridMap& m, const amcl_lite::Pose2& pose,
                                             int max_beams) {
  amcl_lite::ScanObservation scan;
  scan.range_min = 0.45;
  scan.range_max = 8.0;
  const int count = 640;
  const double fov = 58.0 * M_PI / 180.0;
  for (int i : amcl_lite::ParticleFilter::beamIndices(count, max_beams)) {
    const double a = -fov / 2 + fov * i / (count - 1);
    scan.beams.push_back({castRay(m, pose.x, pose.y, pose.theta + a, scan.range_max), a});
  }
  return scan;
}

}  // namespace amcl_lite_test
