// Monte Carlo localization as amcl does it: odometry motion model, likelihood-field laser
// model, KLD-sampling resampling every resample_interval updates, optional random-particle
// injection (augmented MCL), and the pose estimate from the heaviest cluster.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "amcl_lite/amcl_params.h"
#include "amcl_lite/likelihood_field.h"
#include "amcl_lite/pose2.h"

namespace amcl_lite {

struct Particle {
  Pose2 pose;
  double weight = 1.0;
};

// One beam in the laser's frame. Ranges outside [range_min, range_max) carry no hit.
struct Beam {
  double range;
  double angle;
};

struct ScanObservation {
  std::vector<Beam> beams;
  double range_min = 0.0;
  double range_max = 8.0;
  Pose2 laser_in_base;  // the laser's pose in the robot's base frame
};

struct PoseEstimate {
  Pose2 mean;
  std::array<double, 9> covariance{};  // row-major 3x3 over (x, y, yaw)
};

class ParticleFilter {
 public:
  ParticleFilter(const AmclParams& params, std::shared_ptr<const LikelihoodField> field,
                 uint32_t seed = 0);

  // max_particles samples around `mean` (covariance of x, y with their correlation, and yaw).
  void initGaussian(const Pose2& mean, double cov_xx, double cov_yy, double cov_aa,
                    double cov_xy = 0.0);
  // max_particles samples spread uniformly over the map's free cells, any heading.
  void initGlobal();
  // Moves every particle by the odometry step, with noise.
  void predict(const Pose2& old_odom, const Pose2& new_odom);
  // Weighs the particles by the scan; resamples every resample_interval calls.
  void correct(const ScanObservation& scan);

  PoseEstimate estimate() const;
  const std::vector<Particle>& particles() const { return particles_; }
  // Beams of `count` readings the laser model uses: laser_max_beams spread evenly.
  static std::vector<int> beamIndices(int count, int max_beams);

 private:
  void resample();
  size_t kldLimit(size_t bins) const;
  size_t globalParticleCount() const;
  Pose2 randomFreePose();

  AmclParams params_;
  std::shared_ptr<const LikelihoodField> field_;
  std::mt19937 rng_;
  std::vector<Particle> particles_;
  int updates_since_resample_ = 0;
  double w_slow_ = 0.0, w_fast_ = 0.0;
};

}  // namespace amcl_lite
