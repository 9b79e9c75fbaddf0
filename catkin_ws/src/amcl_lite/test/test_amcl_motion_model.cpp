#include <gtest/gtest.h>

#include "amcl_lite/motion_model.h"

using amcl_lite::OdomNoise;
using amcl_lite::Pose2;
using amcl_lite::sampleDiffMotion;

TEST(DiffMotion, WithoutNoiseTheParticleRepeatsTheOdometryStepInItsOwnFrame) {
  std::mt19937 rng(1);
  const OdomNoise none{0, 0, 0, 0};
  const Pose2 old_odom(1, 1, M_PI / 2), new_odom(1, 2, M_PI);  // 1 m ahead, then a left turn
  const Pose2 p = sampleDiffMotion(Pose2(0, 0, 0), old_odom, new_odom, none, rng);
  EXPECT_NEAR(p.x, 1.0, 1e-9);
  EXPECT_NEAR(p.y, 0.0, 1e-9);
  EXPECT_NEAR(p.theta, M_PI / 2, 1e-9);
}

TEST(DiffMotion, ReversingIsNotAHalfTurnOfNoise) {
  std::mt19937 rng(2);
  const OdomNoise noise{0.2, 0.2, 0.2, 0.2};
  double spread = 0.0;
  const int n = 2000;
  for (int i = 0; i < n; ++i) {
    const Pose2 p = sampleDiffMotion(Pose2(0, 0, 0), Pose2(0, 0, 0), Pose2(-0.2, 0, 0), noise, rng);
    spread += p.theta * p.theta;
  }
  // Heading noise from 0.2 m of travel: sigma = sqrt(2 * alpha2) * 0.2 ~ 0.13 rad, not ~pi.
  EXPECT_LT(std::sqrt(spread / n), 0.25);
}
