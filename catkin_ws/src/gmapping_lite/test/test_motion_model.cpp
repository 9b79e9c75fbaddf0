#include <gtest/gtest.h>

#include <cmath>

#include "gmapping_lite/motion_model.h"

using gmapping_lite::MotionModel;
using gmapping_lite::MotionNoise;
using gmapping_lite::Pose2;

TEST(MotionModel, NoMotionNoNoise) {
  MotionModel model(MotionNoise{});
  std::mt19937 rng(3);
  const Pose2 p(1, 2, 0.3);
  const Pose2 s = model.sample(p, Pose2(5, 5, 1), Pose2(5, 5, 1), rng);
  EXPECT_DOUBLE_EQ(s.x, p.x);
  EXPECT_DOUBLE_EQ(s.y, p.y);
  EXPECT_NEAR(s.theta, p.theta, 1e-12);
}

TEST(MotionModel, SamplesCentreOnOdometryAndSpreadWithDistance) {
  MotionModel model(MotionNoise{0.1, 0.2, 0.1, 0.2});
  std::mt19937 rng(5);
  // Odometry moved 1 m forward in a frame rotated by 90 degrees; the particle faces +x.
  const Pose2 old_odom(3, 4, M_PI / 2), new_odom(3, 5, M_PI / 2), start(0, 0, 0);
  auto spread = [&](double scale) {
    const Pose2 far_odom = old_odom * Pose2(scale, 0, 0);
    double mx = 0, my = 0, vx = 0;
    const int n = 4000;
    for (int i = 0; i < n; ++i) {
      const Pose2 s = model.sample(start, old_odom, far_odom, rng);
      mx += s.x;
      my += s.y;
      vx += (s.x - scale) * (s.x - scale);
    }
    EXPECT_NEAR(mx / n, scale, 0.02 * scale);
    EXPECT_NEAR(my / n, 0.0, 0.05 * scale);
    return std::sqrt(vx / n);
  };
  (void)new_odom;
  const double s1 = spread(1.0), s2 = spread(2.0);
  EXPECT_NEAR(s1, 0.1, 0.01);  // srr * 1 m
  EXPECT_GT(s2, 1.7 * s1);
}
