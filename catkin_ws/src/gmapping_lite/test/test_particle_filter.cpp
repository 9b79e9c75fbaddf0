#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>

#include "gmapping_lite/particle_filter.h"
#include "synthetic.h"
#include "gmapping_lite/tuning_file.h"

using namespace gmapping_lite;  // NOLINT: test file

namespace {

// Poses of a trajectory expressed relative to its first pose.
Pose2 fromStart(const Pose2& start, const Pose2& p) { return p.relativeTo(start); }

double rmsError(const std::vector<Pose2>& a, const std::vector<Pose2>& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    s += std::pow(a[i].x - b[i].x, 2) + std::pow(a[i].y - b[i].y, 2);
  return std::sqrt(s / double(a.size()));
}

// The Turtlebot tuning (config/turtlebot.yaml) with 30 particles, as the simulated runs use it.
SlamParams turtlebotParams() {
  SlamParams p;
  const std::string problem = loadTuning(TURTLEBOT_TUNING, &p);
  if (!problem.empty()) ADD_FAILURE() << problem;
  p.particles = 30;
  return p;
}

}  // namespace

TEST(ParticleFilter, MatchEvidenceIsRelativeToTheOtherParticlesMatches) {
  const double none = std::numeric_limits<double>::quiet_NaN();
  // Mean NIS 3 over the matched: +1, 0, -1; a particle without a match: 0.
  std::vector<double> e = relativeMatchEvidence({1.0, 3.0, 5.0, none});
  ASSERT_EQ(e.size(), 4u);
  EXPECT_DOUBLE_EQ(e[0], 1.0);
  EXPECT_DOUBLE_EQ(e[1], 0.0);
  EXPECT_DOUBLE_EQ(e[2], -1.0);
  EXPECT_DOUBLE_EQ(e[3], 0.0);
  // One match turned 90 degrees among consistent ones (NIS (pi/2)^2 / 0.0125 = 197 against
  // about 3): far below the others, whose evidence hardly moves.
  e = relativeMatchEvidence({3.0, 2.0, 197.0, 4.0});
  EXPECT_LT(e[2] - e[0], -90.0);
  EXPECT_NEAR(e[0] - e[1], -0.5, 1e-12);
  // A correction every particle needs (the same large NIS) changes no weight.
  e = relativeMatchEvidence({60.0, 60.0, none});
  for (double x : e) EXPECT_DOUBLE_EQ(x, 0.0);
  // Nothing matched: nothing to compare.
  for (double x : relativeMatchEvidence({none, none})) EXPECT_DOUBLE_EQ(x, 0.0);
}

TEST(ParticleFilter, ProcessesFirstScanThenOnlyAfterEnoughMotion) {
  SlamParams params;
  params.particles = 5;
  params.linear_update = 1.0;
  params.angular_update = 0.5;
  ParticleFilter filter(params);
  const LaserGeometry laser = LaserGeometry::planar(Pose2(), -0.5, 0.1, 11);
  const Ranges ranges(11, 3.0f);
  EXPECT_TRUE(filter.addScan(Pose2(), 0.0, laser, ranges).processed);
  EXPECT_FALSE(filter.addScan(Pose2(0.5, 0, 0), 0.1, laser, ranges).processed);
  EXPECT_FALSE(filter.addScan(Pose2(0.9, 0, 0.2), 0.2, laser, ranges).processed);
  EXPECT_TRUE(filter.addScan(Pose2(1.0, 0, 0.2), 0.3, laser, ranges).processed);
  EXPECT_FALSE(filter.addScan(Pose2(1.0, 0, 0.6), 0.4, laser, ranges).processed);
  EXPECT_TRUE(filter.addScan(Pose2(1.0, 0, 0.75), 0.5, laser, ranges).processed);
  EXPECT_EQ(filter.updates(), 3);
}

TEST(ParticleFilter, TemporalUpdateProcessesAStillRobot) {
  SlamParams params;
  params.particles = 3;
  params.temporal_update = 1.0;
  ParticleFilter filter(params);
  const LaserGeometry laser = LaserGeometry::planar(Pose2(), -0.5, 0.1, 11);
  const Ranges ranges(11, 3.0f);
  EXPECT_TRUE(filter.addScan(Pose2(), 0.0, laser, ranges).processed);
  EXPECT_FALSE(filter.addScan(Pose2(), 0.5, laser, ranges).processed);
  EXPECT_TRUE(filter.addScan(Pose2(), 1.2, laser, ranges).processed);
}

TEST(ParticleFilter, EntropyAndNeffStartUniform) {
  SlamParams params;
  params.particles = 30;
  ParticleFilter filter(params);
  EXPECT_NEAR(filter.neff(), 30.0, 1e-9);
  EXPECT_NEAR(filter.entropy(), std::log(30.0), 1e-9);
}

TEST(ParticleFilter, BeatsOdometryOnTheOfficeTour) {
  const SyntheticWorld world = SyntheticWorld::office();
  RunOptions options;  // Turtlebot-like laser: 640 beams over 58 degrees, 8 m
  const SyntheticRun run = simulateRun(world, officeTour(), options);
  ParticleFilter filter(turtlebotParams());
  std::vector<double> stamps;
  std::vector<Pose2> truth, odom;
  int resamples = 0;
  for (const auto& step : run.steps) {
    const UpdateReport r = filter.addScan(step.odom, step.stamp, run.laser, step.ranges);
    resamples += r.resampled;
    if (!r.processed) continue;
    truth.push_back(fromStart(run.steps.front().truth, step.truth));
    odom.push_back(step.odom);  // odometry starts at zero at the first pose
  }
  // The best particle's trajectory, oldest first.
  std::vector<Pose2> slam;
  for (auto n = filter.best().trajectory; n; n = n->parent) slam.insert(slam.begin(), n->pose);
  ASSERT_EQ(slam.size(), truth.size());
  const double e_odom = rmsError(odom, truth), e_slam = rmsError(slam, truth);
  RecordProperty("odom_rms", std::to_string(e_odom));
  RecordProperty("slam_rms", std::to_string(e_slam));
  std::printf("updates %zu, resamples %d, odometry RMS %.3f m, SLAM RMS %.3f m\n", slam.size(),
              resamples, e_odom, e_slam);
  EXPECT_GT(e_odom, 0.3);  // the odometry really drifts
  EXPECT_LT(e_slam, e_odom / 3.0);
  EXPECT_LT(e_slam, 0.10);
  // The last pose returns to the start: the map frame stays registered.
  EXPECT_LT(std::hypot(slam.back().x - truth.back().x, slam.back().y - truth.back().y), 0.15);
}

TEST(ParticleFilter, ParticlesShareMapMemory) {
  const SyntheticWorld world = SyntheticWorld::office();
  RunOptions options;
  const SyntheticRun run = simulateRun(world, officeTour(), options);
  SlamParams params = turtlebotParams();
  params.particles = 30;
  params.resample_threshold = 1.0;  // resample at every update
  ParticleFilter filter(params);
  int resamples = 0;
  for (std::size_t i = 0; i < run.steps.size() / 3; ++i)
    resamples += filter.addScan(run.steps[i].odom, run.steps[i].stamp, run.laser,
                                run.steps[i].ranges).resampled;
  EXPECT_GT(resamples, 10);
  std::size_t total = 0, shared = 0;
  for (const auto& p : filter.particles()) {
    total += p.map.patchCount();
    shared += p.map.sharedPatchCount();
  }
  // Even right after every particle wrote its latest scan, a good share of each map is
  // still held in common with other particles (the parts no recent scan touched); without
  // copy-on-write sharing it would be none. How much depends on how many distinct lineages
  // survive resampling: 0.42 with the fixed-odometry filter, 0.27 once each particle's Kalman
  // state keeps particles apart (flatter weights), so the floor guards the sharing itself.
  EXPECT_GT(double(shared) / double(total), 0.2);
}

TEST(ParticleFilter, CarriedCovarianceShrinksOnMatchesAndGrowsWithoutThem) {
  const SyntheticWorld world = SyntheticWorld::office();
  RunOptions options;
  const SyntheticRun run = simulateRun(world, officeTour(), options);
  ParticleFilter filter(turtlebotParams());
  const std::size_t half = run.steps.size() / 2;
  double carried = 0.0;  // the particles' position variances, summed
  Pose2 last_odom;  // odometry at the last processed update
  for (std::size_t i = 0; i < half; ++i)
    if (filter.addScan(run.steps[i].odom, run.steps[i].stamp, run.laser, run.steps[i].ranges)
            .processed)
      last_odom = run.steps[i].odom;
  // In the office's rooms the matches keep every particle's pose known to about a
  // centimetre and a degree, where odometry's spreads alone would have grown all along.
  for (const auto& p : filter.particles()) {
    EXPECT_LT(std::sqrt(p.covariance.varXY()), 0.03);
    EXPECT_LT(std::sqrt(p.covariance.varTheta()), 0.02);
    carried += p.covariance.varXY();
  }
  EXPECT_GT(carried, 0.0);  // but never exact
  // Then the laser sees nothing (every beam without a return) while the robot drives on: each
  // update follows odometry exactly and adds its spread to every particle's covariance.
  const Ranges blind(run.steps[half].ranges.size(), std::numeric_limits<float>::infinity());
  auto smallest = [&filter]() {
    double v = INFINITY;
    for (const auto& p : filter.particles()) v = std::min(v, p.covariance.varXY());
    return v;
  };
  double last = smallest();
  int updates = 0;
  for (std::size_t i = half; i < run.steps.size() && updates < 5; ++i) {
    const UpdateReport r = filter.addScan(run.steps[i].odom, run.steps[i].stamp, run.laser, blind);
    if (!r.processed) continue;
    ++updates;
    EXPECT_GT(smallest(), last);
    last = smallest();
    // Each particle's step is odometry's increment since the last update (scaled by the
    // particle's estimate of odometry's scales, which nothing corrects here).
    const Pose2 inc = run.steps[i].odom.relativeTo(last_odom);
    for (const auto& p : filter.particles()) {
      EXPECT_NEAR(p.trajectory->step.x, p.scale.distance * inc.x, 1e-9);
      EXPECT_NEAR(p.trajectory->step.y, p.scale.distance * inc.y, 1e-9);
      EXPECT_NEAR(p.trajectory->step.theta, p.scale.rotation * inc.theta, 1e-9);
    }
    last_odom = run.steps[i].odom;
  }
  EXPECT_EQ(updates, 5);
}

TEST(ParticleFilter, LearnsOdometrysScaleFactors) {
  // A base whose odometry overstates distance by 3 % and turns by 5 % (a wheel radius and a
  // track width off): the matches' corrections, through each particle's covariance of pose and
  // scales, estimate both, and the trajectory stays on the truth.
  const SyntheticWorld world = SyntheticWorld::office();
  RunOptions options;
  options.odom_scale_linear = 0.03;
  options.odom_scale_angular = 0.05;
  const SyntheticRun run = simulateRun(world, officeTour(), options);
  ParticleFilter filter(turtlebotParams());
  for (const auto& step : run.steps) filter.addScan(step.odom, step.stamp, run.laser, step.ranges);
  const OdometryScale& scale = filter.best().scale;
  std::printf("learnt scales: distance %.4f (truth %.4f), rotation %.4f (truth %.4f)\n",
              scale.distance, 1.0 / 1.03, scale.rotation, 1.0 / 1.05);
  EXPECT_NEAR(scale.distance, 1.0 / 1.03, 0.01);
  EXPECT_NEAR(scale.rotation, 1.0 / 1.05, 0.01);
}
