// The Rao-Blackwellized particle filter: each particle owns a pose, a weight, a trajectory
// (a tree shared with its ancestors) and a grid map (patches shared copy-on-write).
#pragma once

#include <memory>
#include <random>
#include <vector>

#include "gmapping_lite/grid_map.h"
#include "gmapping_lite/laser.h"
#include "gmapping_lite/loop_closure.h"
#include "gmapping_lite/motion_model.h"
#include "gmapping_lite/pose2.h"
#include "gmapping_lite/pose_fusion.h"
#include "gmapping_lite/scan_matcher.h"
#include "gmapping_lite/slam_params.h"
#include "gmapping_lite/trajectory.h"

namespace gmapping_lite {

struct Particle {
  Pose2 pose;
  double log_weight = 0.0;  // since the last resampling
  double weight_sum = 0.0;  // over the whole run: picks the best particle
  GridMap map;
  std::shared_ptr<const TrajectoryNode> trajectory;
  // Odometry's variance accumulated since a scan last placed this particle (m^2, rad^2): a
  // match may correct that much on top of the current increment's spread.
  double drift_xy2 = 0.0, drift_theta2 = 0.0;
  // The pose's covariance relative to the particle's own map, carried from update to update
  // (world frame): the prediction's prior is this plus the increment's motion-model spread.
  Covariance covariance;
  OdometryScale scale;  // odometry's scale factors as this particle has estimated them
  Information information;  // of the pose the last match gave (world frame)
  bool placed = true;       // the last scan's pose was known well enough to draw it
};

// What one processed scan did, for diagnostics.
struct UpdateReport {
  bool processed = false;
  int update_index = 0;
  double neff = 0.0;
  bool resampled = false;
  double best_score = 0.0;
  int failed_matches = 0;  // particles whose match scored below minimumScore
  Pose2 best_pose;
  LoopClosureReport loop;       // the back end's attempt at this update
  bool map_rebuilt = false;     // a loop closure moved the trajectory and the map was redrawn
};

// Each particle's log-probability of its match under its own prediction, exp(-NIS / 2) (NIS
// from fuse: the innovation against prediction plus match covariance), relative to the
// update's mean over the particles that matched; 0 for one without a match (NaN). Relative,
// because only differences between particles change their weights: a correction all of them
// need (odometry drifted) weighs nothing, a particle that matched where its prediction says
// it cannot be (a corridor turned 90 degrees) loses, and one whose match failed is taken as
// consistent as the others, neither favoured nor penalised.
std::vector<double> relativeMatchEvidence(const std::vector<double>& nis);

class ParticleFilter {
 public:
  explicit ParticleFilter(const SlamParams& params);

  // Feed one scan with the odometry pose at its time. The scan is processed (motion, match,
  // weight, resample, map update) when it is the first one, or the robot has moved
  // linearUpdate / turned angularUpdate, or temporalUpdate seconds passed.
  UpdateReport addScan(const Pose2& odom, double stamp, const LaserGeometry& laser,
                       const Ranges& ranges);

  const std::vector<Particle>& particles() const { return particles_; }
  std::size_t bestIndex() const;
  const Particle& best() const { return particles_[bestIndex()]; }
  // Normalised weights, effective sample size and entropy of the weights.
  std::vector<double> weights() const;
  double neff() const;
  double entropy() const;

  // The period at which odometry is sampled (s; OdometryPeriod), for the prior's timing term;
  // 0 (the default) while unknown: the term then takes the scan period alone.
  void setOdometryPeriod(double seconds) { odometry_period_ = seconds > 0.0 ? seconds : 0.0; }
  double odometryPeriod() const { return odometry_period_; }

  // map -> odom correction of the best particle at the last processed scan.
  Pose2 mapToOdom() const;
  bool initialized() const { return initialized_; }
  int updates() const { return updates_; }
  const SlamParams& params() const { return params_; }

 private:
  void resample(const std::vector<double>& weights);
  // The odometry prior of a match for the odometry increment `inc`.
  OdometryPrior odometryPrior(const Pose2& inc) const;
  // Back end, on the best particle after an update: the step to its newest node measured
  // against its recent scans only, then a loop closure attempt; on success the trajectory is
  // optimised, the map redrawn from it and every particle continues from the result.
  void backEnd(const ScanPoints& points, const OdometryPrior& prior, UpdateReport* report);
  void closeLoop(const std::vector<const TrajectoryNode*>& chain, UpdateReport* report);
  std::shared_ptr<const LaserGeometry> sharedLaser(const LaserGeometry& laser);
  // A wide search when the climb from the sample found no match; returns the better score
  // and writes the pose when it found one.
  double rescue(const GridMap& map, const Pose2& predicted, const ScanPoints& points,
                const OdometryPrior& prior, double score, Pose2* corrected);

  // The matches' dispersion so far, and a particle's scales as they enter its prediction (1
  // where its estimate does not differ from 1 significantly).
  double dispersion() const;
  OdometryScale significantScale(const Particle& p) const;
  double nis_sum_ = 0.0, nis_expected_ = 0.0;
  SlamParams params_;
  MotionModel motion_;
  ScanMatcher matcher_;
  ScanMatcher local_matcher_;  // the back end's, against the recent scans
  LoopCloser loop_closer_;
  std::vector<PoseEdge> loops_;  // loop edges found so far (node indices)
  std::shared_ptr<const LaserGeometry> laser_;  // the last laser geometry, shared by nodes
  std::mt19937 rng_;
  std::vector<Particle> particles_;
  bool initialized_ = false;
  int updates_ = 0;
  Pose2 last_odom_;         // odometry at the last processed scan
  Pose2 previous_odom_;     // odometry at the last scan seen (for distance accumulation)
  double linear_distance_ = 0.0, angular_distance_ = 0.0;
  double last_update_stamp_ = 0.0;
  double previous_stamp_ = 0.0;  // stamp of the last scan seen
  double scan_period_ = 0.0;     // running mean of the interval between scans (s)
  double odometry_period_ = 0.0;  // odometry's sample period (s), 0 while unknown
  double speed_ = 0.0, turn_rate_ = 0.0;  // odometry's forward and turn rate at the last scan
  double last_update_speed_ = 0.0, last_update_turn_rate_ = 0.0;  // at the last update
};

}  // namespace gmapping_lite
