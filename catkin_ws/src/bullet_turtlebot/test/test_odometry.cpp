#include <gtest/gtest.h>

#include <cmath>

#include "bullet_turtlebot/odometry.hpp"

using namespace bullet_turtlebot;

namespace {

Pose2D drive_square(std::uint64_t seed, bool noise) {
  OdometryNoise n;
  n.enabled = noise;
  OdometryModel odom(n, seed);
  for (int side = 0; side < 4; ++side) {
    for (int i = 0; i < 200; ++i) odom.update(0.005, 0.0, 0.01);     // 1 m
    for (int i = 0; i < 100; ++i) odom.update(0.0, M_PI / 200, 0.01);  // 90 degrees
  }
  return odom.pose();
}

}  // namespace

TEST(Odometry, ExactWithoutNoise) {
  const Pose2D p = drive_square(1, false);
  EXPECT_NEAR(p.x, 0.0, 1e-9);
  EXPECT_NEAR(p.y, 0.0, 1e-9);
}

TEST(Odometry, SameSeedSameDriftOtherSeedOtherDrift) {
  const Pose2D a = drive_square(7, true), b = drive_square(7, true), c = drive_square(8, true);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.yaw, b.yaw);
  EXPECT_NE(a.x, c.x);
}

TEST(Odometry, DriftIsRealisticNotAbsurd) {
  // Over a 4 m square loop the default model should be off by centimetres to decimetres.
  double sum = 0;
  int drifted = 0;
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    const Pose2D p = drive_square(seed, true);
    const double err = std::hypot(p.x, p.y);
    sum += err;
    drifted += err > 0.005;
  }
  const double mean = sum / 50;
  EXPECT_GT(mean, 0.01);
  EXPECT_LT(mean, 0.4);
  EXPECT_GT(drifted, 40);
}

TEST(Odometry, NoCreepAtRest) {
  OdometryModel odom(OdometryNoise{}, 3);
  for (int i = 0; i < 10000; ++i) odom.update(0.0, 0.0, 0.01);
  EXPECT_EQ(odom.pose().x, 0.0);
  EXPECT_EQ(odom.pose().y, 0.0);
  EXPECT_EQ(odom.pose().yaw, 0.0);
}
