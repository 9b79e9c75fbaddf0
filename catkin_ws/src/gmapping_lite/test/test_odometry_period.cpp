#include <gtest/gtest.h>

#include "gmapping_lite/odometry_period.h"

using gmapping_lite::OdometryPeriod;

TEST(OdometryPeriod, UnknownUntilTwoDistinctStamps) {
  OdometryPeriod p;
  EXPECT_FALSE(p.known());
  EXPECT_EQ(p.period(), 0.0);
  p.add(10.0);
  EXPECT_FALSE(p.known());
  p.add(10.0);  // the same sample again
  EXPECT_FALSE(p.known());
  EXPECT_EQ(p.period(), 0.0);
  p.add(10.02);
  EXPECT_TRUE(p.known());
  EXPECT_NEAR(p.period(), 0.02, 1e-12);
}

TEST(OdometryPeriod, RegularStamps) {
  OdometryPeriod p;
  for (int i = 0; i < 200; ++i) p.add(100.0 + 0.02 * i);  // 50 Hz, like a Kobuki base
  EXPECT_NEAR(p.period(), 0.02, 1e-9);
}

TEST(OdometryPeriod, DuplicatesAreOneSample) {
  // Each sample sent three times (several tf messages carrying the same transform): the
  // period is the samples', not a third of it, and no zero intervals pull the median down.
  OdometryPeriod p;
  for (int i = 0; i < 100; ++i)
    for (int k = 0; k < 3; ++k) p.add(5.0 + 0.1 * i);
  EXPECT_NEAR(p.period(), 0.1, 1e-9);
}

TEST(OdometryPeriod, AGapDoesNotMoveIt) {
  OdometryPeriod p;
  double t = 0.0;
  for (int i = 0; i < 40; ++i) p.add(t += 0.1);
  p.add(t += 3.0);  // the publisher paused
  for (int i = 0; i < 5; ++i) p.add(t += 0.1);
  EXPECT_NEAR(p.period(), 0.1, 1e-9);
  // Nor do lost samples, while fewer than half the window's intervals.
  for (int i = 0; i < 20; ++i) p.add(t += (i % 2 ? 0.2 : 0.1));
  EXPECT_NEAR(p.period(), 0.1, 1e-9);
}

TEST(OdometryPeriod, FollowsARateChangeWithinTheWindow) {
  OdometryPeriod p(11);
  double t = 0.0;
  for (int i = 0; i < 30; ++i) p.add(t += 0.1);
  for (int i = 0; i < 5; ++i) p.add(t += 0.02);
  EXPECT_NEAR(p.period(), 0.1, 1e-9);  // 5 of 11: not yet
  for (int i = 0; i < 6; ++i) p.add(t += 0.02);
  EXPECT_NEAR(p.period(), 0.02, 1e-9);
}

TEST(OdometryPeriod, TimeJumpingBackResets) {
  OdometryPeriod p;
  for (int i = 0; i < 50; ++i) p.add(200.0 + 0.1 * i);
  EXPECT_NEAR(p.period(), 0.1, 1e-9);
  p.add(1.0);  // a bag played again from its start
  EXPECT_FALSE(p.known());
  EXPECT_EQ(p.period(), 0.0);
  p.add(1.02);
  p.add(1.04);
  EXPECT_NEAR(p.period(), 0.02, 1e-9);  // the old rate is forgotten
}
