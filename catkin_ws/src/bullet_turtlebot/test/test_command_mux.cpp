#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "bullet_turtlebot/command_mux.hpp"

using namespace bullet_turtlebot;

TEST(CommandMux, PrioritiesAndTimeouts) {
  CommandMux mux(turtlebot_mux_inputs());  // 0 safety (10, 0.2 s), 1 teleop (7, 1 s), 2 navi (5, 1 s)
  EXPECT_TRUE(mux.offer(2, 0.0));          // navi alone drives
  EXPECT_TRUE(mux.offer(1, 0.1));          // teleop overrides navi
  EXPECT_FALSE(mux.offer(2, 0.2));         // navi blocked while teleop is live
  EXPECT_EQ(mux.active(0.5), 1);
  EXPECT_TRUE(mux.offer(0, 0.5));          // safety overrides teleop
  EXPECT_FALSE(mux.offer(1, 0.6));
  EXPECT_TRUE(mux.offer(1, 0.75));         // safety timed out after 0.2 s
  EXPECT_FALSE(mux.offer(2, 1.7));         // teleop still live (1.0 s timeout)
  EXPECT_TRUE(mux.offer(2, 1.8));
}

TEST(CommandCheck, RejectsNonFiniteAndHuge) {
  const double zero[3] = {0, 0, 0};
  const double ok[3] = {0.5, 0, 0};
  const double nan[3] = {std::nan(""), 0, 0};
  const double inf[3] = {0, 0, std::numeric_limits<double>::infinity()};
  const double huge[3] = {1e6, 0, 0};
  EXPECT_EQ(check_command(ok, zero, 10, 20), CommandCheck::kOk);
  EXPECT_EQ(check_command(nan, zero, 10, 20), CommandCheck::kNotFinite);
  EXPECT_EQ(check_command(zero, inf, 10, 20), CommandCheck::kNotFinite);
  EXPECT_EQ(check_command(huge, zero, 10, 20), CommandCheck::kTooLarge);
  EXPECT_EQ(check_command(zero, huge, 10, 20), CommandCheck::kTooLarge);
}
