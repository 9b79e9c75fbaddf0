// Scan matcher in gmapping's spirit with a likelihood field: each beam end point is scored by
// its distance d to the nearest occupied cell (to its wall's line on walls, see MatchField),
// exp(-d^2 / 2 sigma^2). The pose is found by hill climbing over x, y and yaw with a widened
// kernel (steps lstep / 2^k and astep / 2^k at level k, under gmapping's odometry-reliability
// prior), then polished by a few point-to-line ICP steps against the same field.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "gmapping_lite/grid_map.h"
#include "gmapping_lite/laser.h"
#include "gmapping_lite/match_field.h"
#include "gmapping_lite/pose2.h"

namespace gmapping_lite {

struct MatcherParams {
  double sigma = 0.05;       // score kernel: exp(-d^2 / 2 sigma^2)
  int kernel_size = 1;       // level k uses sigma x max(1, 2^(kernel_size + 1 - k))
  double lstep = 0.05;       // initial translational step (m)
  double astep = 0.05;       // initial angular step (rad)
  int iterations = 5;        // coarse-to-fine levels (steps halve at each)
  double lsigma = 0.075;     // likelihood per beam: -d^2 / 2 lsigma^2, d capped at 3 lsigma
  int lskip = 0;             // use every (lskip + 1)-th beam for matching
  double max_range = 8.0;    // returns beyond this are ignored
  double max_urange = 8.0;   // returns beyond this clear space but mark nothing
  double fullness = 0.1;     // a cell with occupancy above this counts as occupied
  double field_radius = 0.3; // how far the likelihood field looks for occupied cells (m)
};

// How far odometry's guess may be off (standard deviations): a candidate's score is
// multiplied by exp(-d^2 / 2 sigma_xy^2 - dtheta^2 / 2 sigma_theta^2) for its distance from the
// guess (gmapping's "odometry reliability"), so a featureless corridor or a lone wall cannot
// drag the pose away from where odometry put it. sigma <= 0 disables a term.
struct OdometryPrior {
  double sigma_xy = 0.0;
  double sigma_theta = 0.0;
};

// The beams of one scan that matching uses, as end points in the base frame.
struct ScanPoints {
  struct Point {
    double hx, hy;  // end point
  };
  std::vector<Point> points;
};

class ScanMatcher {
 public:
  explicit ScanMatcher(const MatcherParams& params);

  const MatcherParams& params() const { return params_; }

  ScanPoints matchPoints(const LaserGeometry& laser, const Ranges& ranges) const;

  // Prepare the field around `pose` for the given scan points.
  void prepare(const GridMap& map, const Pose2& pose, const ScanPoints& scan);

  double score(const Pose2& pose, const ScanPoints& scan) const;
  // Log-likelihood of the scan at `pose`, and its score.
  double likelihood(const Pose2& pose, const ScanPoints& scan, double* score) const;
  // Hill-climb from `start`; returns the best score and writes the best pose.
  double optimize(const Pose2& start, const ScanPoints& scan, Pose2* best,
                  const OdometryPrior& prior = {}) const;

  // Convenience: prepare + optimize against `map`.
  double match(const GridMap& map, const Pose2& start, const ScanPoints& scan, Pose2* best,
               const OdometryPrior& prior = {});

 private:
  double scoreAt(const Pose2& pose, const ScanPoints& scan, double inv_two_sigma2) const;
  // Gauss-Newton ICP (point-to-line on walls) against the field: finds the score's peak along
  // diagonal ridges that axis-aligned climbing stalls on.
  // `guess` and `prior` keep directions the scan does not constrain (a corridor) at odometry's.
  Pose2 refine(const Pose2& start, const ScanPoints& scan, const Pose2& guess,
               const OdometryPrior& prior) const;

  MatcherParams params_;
  MatchField field_;
  std::vector<MatchField::Point> focus_;  // scratch: the scan's end points in the world
};

// Enter one scan into a map at `pose` (all usable beams, not just the matching subset).
void registerScan(GridMap* map, const Pose2& pose, const LaserGeometry& laser,
                  const Ranges& ranges, double max_range, double max_urange);

}  // namespace gmapping_lite
