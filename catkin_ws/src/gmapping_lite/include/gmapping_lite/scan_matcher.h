// Scan matcher in gmapping's spirit with a likelihood field (see MatchField). Each beam end
// point is judged by what the particle's map says of it: near an occupied cell reached from its
// seen side, it scores by its distance d (to the wall's line on walls) as a Gaussian mixed with
// gmapping's null likelihood (a beam 3 sigma off); in space the map has seen free, or through a
// wall from behind, it contradicts the map (the null likelihood); in space never seen it is
// neutral (half way, in log terms). The pose maximises the scan's log-likelihood plus the
// odometry prior: hill climbing over x, y and yaw with a widened kernel (steps lstep / 2^k and
// astep / 2^k at level k), then polished by point-to-line Gauss-Newton steps.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "gmapping_lite/grid_map.h"
#include "gmapping_lite/laser.h"
#include "gmapping_lite/match_field.h"
#include "gmapping_lite/pose2.h"
#include "gmapping_lite/pose_graph.h"

namespace gmapping_lite {

struct MatcherParams {
  double sigma = 0.05;       // score kernel: exp(-d^2 / 2 sigma^2)
  int kernel_size = 1;       // level k uses sigma x max(1, 2^(kernel_size + 1 - k))
  double lstep = 0.05;       // initial translational step (m)
  double astep = 0.05;       // initial angular step (rad)
  int iterations = 5;        // coarse-to-fine levels (steps halve at each)
  double lsigma = 0.075;     // likelihood per beam: Gaussian in d, floored at 3 lsigma off
  int lskip = 0;             // use every (lskip + 1)-th beam for matching
  double max_range = 8.0;    // returns beyond this are ignored
  double max_urange = 8.0;   // returns beyond this clear space but mark nothing
  double fullness = 0.1;     // a cell with occupancy above this counts as occupied
  double field_radius = 0.3; // how far the likelihood field looks for occupied cells (m)
  // Consecutive beams whose end points lie within this of each other are matched as one point
  // standing for all of them (0: every beam on its own). The filter sets it to the map's
  // resolution: the map cannot tell such end points apart, so they are one observation.
  double merge_distance = 0.0;
};

// How far odometry's guess may be off (standard deviations): a candidate's log-posterior gains
// -d^2 / 2 sigma_xy^2 - dtheta^2 / 2 sigma_theta^2 for its distance from the guess (gmapping's
// "odometry reliability"), so a featureless corridor or a lone wall cannot drag the pose away
// from where odometry put it. sigma <= 0 disables a term.
struct OdometryPrior {
  double sigma_xy = 0.0;
  double sigma_theta = 0.0;
};

// The beams of one scan that matching uses, in the base frame.
struct ScanPoints {
  struct Point {
    double hx, hy;  // end point
    double ux, uy;  // unit direction of the beam (from the laser towards the end point)
    double beams;   // how many beams this point stands for
  };
  std::vector<Point> points;
  double beams = 0.0;  // sum of the points' beams
};

class ScanMatcher {
 public:
  explicit ScanMatcher(const MatcherParams& params);

  const MatcherParams& params() const { return params_; }

  ScanPoints matchPoints(const LaserGeometry& laser, const Ranges& ranges) const;

  // Prepare the field around `pose` for the given scan points; `search` (m) widens the part
  // of the map covered, for a search over a window rather than a climb from a good guess.
  void prepare(const GridMap& map, const Pose2& pose, const ScanPoints& scan,
               double search = 0.0);

  // gmapping's match score: sum over beams of exp(-d^2 / 2 sigma^2) for matched end points.
  double score(const Pose2& pose, const ScanPoints& scan) const;
  // Log-likelihood of the scan at `pose` (per beam, with lsigma), and its score.
  double likelihood(const Pose2& pose, const ScanPoints& scan, double* score) const;
  // The points of `all` whose end point lies in space the map has seen (matched or
  // contradicting the map, not unknown) at `pose` and at `pose` moved by +-reach along x and
  // along y. A point that crosses into unknown space within a climb's reach would make the
  // climb's objective lopsided: it scores as matched on the mapped side and not at all beyond,
  // so the end points near the mapped end of a wall along the motion would hold the match
  // back from moving forward while moving backward costs nothing.
  ScanPoints knownPoints(const Pose2& pose, const ScanPoints& all, double reach) const;
  // Maximise log-likelihood + prior from `start` (the prior's centre); returns the score at
  // the best pose and writes it.
  double optimize(const Pose2& start, const ScanPoints& scan, Pose2* best,
                  const OdometryPrior& prior = {}) const;
  // The same from `start`, with the prior centred on `centre`.
  double optimizeFrom(const Pose2& start, const Pose2& centre, const ScanPoints& scan,
                      Pose2* best, const OdometryPrior& prior) const;

  // The log-posterior a match maximises (fine kernel): one term per point plus the prior.
  double objective(const Pose2& pose, const Pose2& centre, const ScanPoints& scan,
                   const OdometryPrior& prior) const;

  // How well the scan pins `pose` down (world frame, points in units of sigma), plus the
  // prior's own information.
  Information information(const Pose2& pose, const ScanPoints& scan,
                          const OdometryPrior& prior) const;

  // How well the scan pins `pose` down as a measurement of it (world frame, no prior): one
  // observation per point, whatever the beams it stands for, at lsigma. The map holds each
  // wall somewhere within a cell, and the beams ending in one cell (merge_distance) all look at
  // that one record, so they are one observation, not many; lsigma is gmapping's spread of one
  // observation about the map (the particle weights' likelihood). `information` counts every
  // beam at sigma, five to ten times as much: right for the climb's shape, not for the pose's
  // error.
  Information calibratedInformation(const Pose2& pose, const ScanPoints& scan) const;

  // Points at `pose` that land on a mapped cell (within 2 sigma), and that contradict the map.
  void agreement(const Pose2& pose, const ScanPoints& scan, int* matched, int* contradicting) const;

  // Exhaustive search of x, y within +-window_xy and yaw within +-window_theta of `centre` in
  // steps of step_xy and step_theta, scoring the points' log-likelihood with a kernel as wide
  // as step_xy. Returns every pose tried with its score.
  struct Candidate {
    Pose2 pose;
    double value;
  };
  std::vector<Candidate> search(const Pose2& centre, const ScanPoints& scan, double window_xy,
                                double window_theta, double step_xy, double step_theta) const;

  // How far `top`, the best of a search's `grid`, leads the best candidate outside its own
  // uncertainty (three standard deviations of `info`, the match's information, counted beyond
  // one grid step): the length of a corridor, where any place fits as well, is not a rival.
  // +infinity when nothing lies outside. A lead below log(grid.size()) nats is what comparing
  // that many places produces by chance: the match is ambiguous (a pillar seen from any side,
  // one rack among a row of equal racks).
  static double margin(const std::vector<Candidate>& grid, const Candidate& top,
                       const Information& info, double step_xy, double step_theta);

  // Convenience: prepare + optimize against `map`.
  double match(const GridMap& map, const Pose2& start, const ScanPoints& scan, Pose2* best,
               const OdometryPrior& prior = {});

 private:
  // Sum over points of the log-likelihood with kernel sigma (inv = 1 / 2 sigma^2), each point's
  // term counted once per beam it stands for (as in the weights and the normal equations).
  double pointLogLikelihood(const Pose2& pose, const ScanPoints& scan, double inv) const;
  // Gauss-Newton (point-to-line on walls) against the field: finds the peak along diagonal
  // ridges that axis-aligned climbing stalls on. `centre` and `prior` keep directions the scan
  // does not constrain (a corridor) at odometry's.
  Pose2 refine(const Pose2& start, const ScanPoints& scan, const Pose2& centre,
               const OdometryPrior& prior) const;
  // Gauss-Newton normal equations h, g of the matched points at `pose` (each point weighted by
  // its beams, or by one with per_beam false); returns the number of pairs.
  int normalEquations(const Pose2& pose, const ScanPoints& scan, double h[3][3],
                      double g[3], bool per_beam = true) const;
  // `pose` with its offset from `centre` removed along the directions the scan constrains
  // less than the prior does.
  Pose2 keepUnconstrained(const Pose2& pose, const Pose2& centre, const ScanPoints& scan,
                          const OdometryPrior& prior) const;

  MatcherParams params_;
  MatchField field_;
  std::vector<MatchField::Point> focus_;  // scratch: the scan's end points in the world
};

// Enter one scan into a map at `pose` (all usable beams, not just the matching subset).
void registerScan(GridMap* map, const Pose2& pose, const LaserGeometry& laser,
                  const Ranges& ranges, double max_range, double max_urange);

}  // namespace gmapping_lite
