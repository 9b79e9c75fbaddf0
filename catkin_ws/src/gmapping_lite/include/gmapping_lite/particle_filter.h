// The Rao-Blackwellized particle filter: each particle owns a pose, a weight, a trajectory
// (a tree shared with its ancestors) and a grid map (patches shared copy-on-write).
#pragma once

#include <memory>
#include <random>
#include <vector>

#include "gmapping_lite/grid_map.h"
#include "gmapping_lite/laser.h"
#include "gmapping_lite/motion_model.h"
#include "gmapping_lite/pose2.h"
#include "gmapping_lite/scan_matcher.h"
#include "gmapping_lite/slam_params.h"

namespace gmapping_lite {

struct TrajectoryNode {
  Pose2 pose;
  double stamp = 0.0;
  std::shared_ptr<const TrajectoryNode> parent;
};

struct Particle {
  Pose2 pose;
  double log_weight = 0.0;  // since the last resampling
  double weight_sum = 0.0;  // over the whole run: picks the best particle
  GridMap map;
  std::shared_ptr<const TrajectoryNode> trajectory;
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
};

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

  // map -> odom correction of the best particle at the last processed scan.
  Pose2 mapToOdom() const;
  bool initialized() const { return initialized_; }
  int updates() const { return updates_; }
  const SlamParams& params() const { return params_; }

 private:
  void resample(const std::vector<double>& weights);

  SlamParams params_;
  MotionModel motion_;
  ScanMatcher matcher_;
  std::mt19937 rng_;
  std::vector<Particle> particles_;
  bool initialized_ = false;
  int updates_ = 0;
  Pose2 last_odom_;         // odometry at the last processed scan
  Pose2 previous_odom_;     // odometry at the last scan seen (for distance accumulation)
  double linear_distance_ = 0.0, angular_distance_ = 0.0;
  double last_update_stamp_ = 0.0;
};

}  // namespace gmapping_lite
