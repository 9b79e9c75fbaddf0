#include <gtest/gtest.h>

#include <memory>

#include "amcl_lite/particle_filter.h"
#include "synthetic_world.h"

using amcl_lite::AmclParams;
using amcl_lite::LikelihoodField;
using amcl_lite::ParticleFilter;
using amcl_lite::Pose2;

namespace {

double positionError(const ParticleFilter& pf, const Pose2& truth) {
  const auto e = pf.estimate();
  return std::hypot(e.mean.x - truth.x, e.mean.y - truth.y);
}

// Drives the true robot and the filter's odometry along the same steps; the odometry
// over-reads distance by 5% (drift) so the filter has something to correct.
void drive(ParticleFilter* pf, const amcl_lite::GridMap& map, Pose2* truth, Pose2* odom,
           const Pose2& step, int steps) {
  const Pose2 drifted(step.x * 1.05, step.y, step.theta);
  for (int i = 0; i < steps; ++i) {
    const Pose2 old_odom = *odom;
    *truth = *truth * step;
    *odom = *odom * drifted;
    pf->predict(old_odom, *odom);
    pf->correct(amcl_lite_test::kinectScan(map, *truth, 30));
  }
}

}  // namespace

TEST(ParticleFilter, BeamIndicesSpanTheWholeScan) {
  const auto idx = ParticleFilter::beamIndices(640, 30);
  ASSERT_EQ(idx.size(), 30u);
  EXPECT_EQ(idx.front(), 0);
  EXPECT_EQ(idx.back(), 639);
  EXPECT_EQ(ParticleFilter::beamIndices(10, 30).size(), 10u);
}

TEST(ParticleFilter, ConvergesFromAnOffsetInitialPoseWithTheNarrowKinectScan) {
  const auto map = amcl_lite_test::room();
  auto field = std::make_shared<const LikelihoodField>(map, 2.0);
  AmclParams p;
  Pose2 truth(1.0, 0.0, 0.3);
  // An rviz-style initial pose 0.4 m and 0.2 rad off, with amcl's default spread.
  p.initial_pose_x = truth.x + 0.3;
  p.initial_pose_y = truth.y - 0.25;
  p.initial_pose_a = truth.theta + 0.2;
  ParticleFilter pf(p, field, 7);
  Pose2 odom(0, 0, 0);
  drive(&pf, map, &truth, &odom, Pose2(0, 0, 0.25), 6);   // look around
  drive(&pf, map, &truth, &odom, Pose2(0.2, 0, 0.0), 10);  // drive 2 m
  EXPECT_LT(positionError(pf, truth), 0.15);
  EXPECT_LT(std::fabs(amcl_lite::normalizeAngle(pf.estimate().mean.theta - truth.theta)), 0.1);
  // KLD sampling shrank the cloud from max_particles once it converged.
  EXPECT_LT(pf.particles().size(), static_cast<size_t>(p.max_particles));
  EXPECT_GE(pf.particles().size(), 100u);
}

TEST(ParticleFilter, GlobalLocalizationFindsTheRobotInAnAsymmetricRoom) {
  const auto map = amcl_lite_test::room();
  auto field = std::make_shared<const LikelihoodField>(map, 2.0);
  AmclParams p;
  p.max_particles = 20000;
  p.update_min_a = 0.2;
  ParticleFilter pf(p, field, 3);
  pf.initGlobal();
  Pose2 truth(2.0, 2.0, 0.0), odom(0, 0, 0);
  drive(&pf, map, &truth, &odom, Pose2(0, 0, 0.35), 36);  // two full turns in place
  drive(&pf, map, &truth, &odom, Pose2(0.15, 0, 0.0), 6);
  EXPECT_LT(positionError(pf, truth), 0.3);
}

TEST(ParticleFilter, GlobalLocalizationWithTheTurtlebotTuningFindsTheRobot) {
  // amcl.launch's particle counts: max_particles alone spread over the room leaves the
  // truth's neighbourhood empty, so the global cloud is larger and thinned once it has
  // converged enough.
  const auto map = amcl_lite_test::room();
  auto field = std::make_shared<const LikelihoodField>(map, 2.0);
  AmclParams p;
  p.min_particles = 500;
  p.max_particles = 2000;
  p.kld_err = 0.05;
  p.resample_interval = 1;
  ParticleFilter pf(p, field, 5);
  pf.initGlobal();
  // ln(1 / (1 - kld_z)) per 0.5 m x 0.5 m x 10 degree bin of the room's ~44 m^2 of free space.
  EXPECT_GT(pf.particles().size(), 20u * static_cast<size_t>(p.max_particles) / 2);
  Pose2 truth(3.0, 3.0, 2.0), odom(0, 0, 0);
  drive(&pf, map, &truth, &odom, Pose2(0, 0, 0.2), 34);  // a full turn in place
  drive(&pf, map, &truth, &odom, Pose2(0.15, 0, 0.0), 6);
  EXPECT_LT(positionError(pf, truth), 0.3);
  EXPECT_LE(pf.particles().size(), static_cast<size_t>(p.max_particles));
}

TEST(ParticleFilter, RefusesInvalidParameters) {
  const auto map = amcl_lite_test::room();
  auto field = std::make_shared<const LikelihoodField>(map, 2.0);
  AmclParams p;
  p.min_particles = 0;
  EXPECT_THROW(ParticleFilter(p, field), std::invalid_argument);
}
