#include <gtest/gtest.h>

#include <cmath>

#include "bullet_turtlebot/diff_drive.hpp"

using namespace bullet_turtlebot;

TEST(DiffDrive, StraightLine) {
  Pose2D p{1.0, 2.0, M_PI / 2};
  p = integrate_arc(p, 0.5, 0.0, 2.0);
  EXPECT_NEAR(p.x, 1.0, 1e-12);
  EXPECT_NEAR(p.y, 3.0, 1e-12);
  EXPECT_NEAR(p.yaw, M_PI / 2, 1e-12);
}

TEST(DiffDrive, ArcMatchesCircleAndIsStepSizeIndependent) {
  // Half a circle of radius 1: v = 1, w = 1, t = pi.
  Pose2D one = integrate_arc(Pose2D{}, 1.0, 1.0, M_PI);
  EXPECT_NEAR(one.x, 0.0, 1e-9);
  EXPECT_NEAR(one.y, 2.0, 1e-9);
  EXPECT_NEAR(std::abs(one.yaw), M_PI, 1e-9);
  Pose2D many;
  for (int i = 0; i < 1000; ++i) many = integrate_arc(many, 1.0, 1.0, M_PI / 1000);
  EXPECT_NEAR(many.x, one.x, 1e-9);
  EXPECT_NEAR(many.y, one.y, 1e-9);
}

TEST(DiffDrive, TurnInPlaceDoesNotTranslate) {
  Pose2D p{0.3, -0.2, 0.1};
  p = integrate_arc(p, 0.0, 2.0, 0.5);
  EXPECT_DOUBLE_EQ(p.x, 0.3);
  EXPECT_DOUBLE_EQ(p.y, -0.2);
  EXPECT_NEAR(p.yaw, 1.1, 1e-12);
}

TEST(DiffDrive, RampRespectsAcceleration) {
  double v = 0.0;
  for (int i = 0; i < 10; ++i) v = ramp(v, 0.5, 1.0, 0.01);
  EXPECT_NEAR(v, 0.1, 1e-12);
  for (int i = 0; i < 100; ++i) v = ramp(v, 0.5, 1.0, 0.01);
  EXPECT_DOUBLE_EQ(v, 0.5);
}

TEST(DiffDrive, ClampToKobukiLimits) {
  DriveLimits limits;
  double v = 3.0, w = -9.0;
  clamp_command(limits, &v, &w);
  EXPECT_DOUBLE_EQ(v, limits.max_linear);
  EXPECT_DOUBLE_EQ(w, -limits.max_angular);
}
