// Synthetic data for tests and benchmarks: a known occupancy grid, a ray caster, and a robot
// driven along waypoints whose odometry drifts the way a real base's does.
#pragma once

#include <vector>

#include "gmapping_lite/laser.h"
#include "gmapping_lite/pose2.h"

namespace gmapping_lite {

class SyntheticWorld {
 public:
  SyntheticWorld(double width, double height, double resolution);

  // Rooms with doorways and a few boxes, 16 m x 10 m, origin at the lower-left corner.
  static SyntheticWorld office();

  void fillRect(double x0, double y0, double x1, double y1, bool occupied = true);
  bool occupied(double x, double y) const;
  // Distance to the first occupied cell along the ray, or +inf beyond max_range.
  double castRay(double x, double y, double angle, double max_range) const;

  double width() const { return width_; }
  double height() const { return height_; }
  double resolution() const { return res_; }
  // Distance from (x, y) to the nearest occupied cell centre, searched within `radius`.
  double distanceToWall(double x, double y, double radius) const;

 private:
  bool cellOccupied(int i, int j) const;
  double width_, height_, res_;
  int nx_, ny_;
  std::vector<unsigned char> cells_;
};

struct RunOptions {
  int beams = 640;
  double fov = 1.0123;  // 58 degrees, the Turtlebot's fake laser
  double range_min = 0.45, range_max = 8.0;
  double range_noise = 0.005;  // m, Gaussian
  double scan_rate = 10.0;     // Hz
  double speed = 0.3;          // m/s
  double turn_rate = 0.6;      // rad/s
  // Odometry errors: scale errors (fractions) and per-step random noise; about what the
  // simulator's Kobuki drifts (around 1 m RMS over a 5-minute tour).
  double odom_scale_linear = 0.01, odom_scale_angular = 0.02;
  double odom_noise_linear = 0.01, odom_noise_angular = 0.02;
  unsigned seed = 1;
};

struct SyntheticStep {
  double stamp;
  Pose2 truth;
  Pose2 odom;
  Ranges ranges;
};

struct SyntheticRun {
  LaserGeometry laser;
  std::vector<SyntheticStep> steps;
};

// Drive through `waypoints` (turn in place, then straight), scanning at scan_rate.
SyntheticRun simulateRun(const SyntheticWorld& world, const std::vector<Pose2>& waypoints,
                         const RunOptions& options);

// A loop through the rooms of SyntheticWorld::office().
std::vector<Pose2> officeTour();

}  // namespace gmapping_lite
