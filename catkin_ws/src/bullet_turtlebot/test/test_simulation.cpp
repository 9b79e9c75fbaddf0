#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "bullet_turtlebot/simulation.hpp"
#include "test_helpers.hpp"

using namespace bullet_turtlebot;

namespace {

SimulationConfig quiet_config() {
  SimulationConfig config;
  config.odometry.enabled = false;
  return config;
}

std::shared_ptr<const World> wall_at(double x) {
  return std::make_shared<const World>(testing_helpers::wall_world(x));
}

// Commands (v, w) every 0.1 s (like a teleop node) for `seconds`.
void drive(Simulation& sim, double v, double w, double seconds) {
  const int steps = static_cast<int>(std::lround(seconds / sim.config().step));
  for (int i = 0; i < steps; ++i) {
    if (i % 10 == 0) sim.command(v, w);
    sim.step();
  }
}

}  // namespace

TEST(Simulation, DrivesAboutOneMetreInTwoSeconds) {
  Simulation sim(wall_at(50.0), quiet_config(), Pose2D{});
  drive(sim, 0.5, 0.0, 2.0);
  // Ramp at 2 m/s^2 costs 0.0625 m.
  EXPECT_NEAR(sim.pose().x, 1.0 - 0.0625, 0.01);
  EXPECT_NEAR(sim.odometry().pose().x, sim.pose().x, 1e-6);
}

TEST(Simulation, WatchdogStopsTheRobot) {
  Simulation sim(wall_at(50.0), quiet_config(), Pose2D{});
  sim.command(0.5, 0.0);
  for (int i = 0; i < 300; ++i) sim.step();
  // Moving for 0.6 s, then stopping within the deceleration ramp.
  EXPECT_DOUBLE_EQ(sim.linear_velocity(), 0.0);
  EXPECT_LT(sim.pose().x, 0.5 * 0.6 + 0.1);
  const double x = sim.pose().x;
  for (int i = 0; i < 1000; ++i) sim.step();
  EXPECT_EQ(sim.pose().x, x);  // no creeping
}

TEST(Simulation, StopsAtWallWithBumperAndNoTunnelling) {
  Simulation sim(wall_at(1.0), quiet_config(), Pose2D{});
  bool pressed = false;
  for (int i = 0; i < 500; ++i) {
    if (i % 10 == 0) sim.command(0.7, 0.0);
    for (const auto& c : sim.step()) {
      if (c.bumper == kBumperCenter && c.pressed) pressed = true;
    }
  }
  EXPECT_TRUE(pressed);
  EXPECT_TRUE(sim.bumpers()[kBumperCenter]);
  EXPECT_NEAR(sim.pose().x, 1.0 - 0.18, 0.01);
  EXPECT_LE(sim.pose().x, 1.0 - 0.18 + 1e-3);
  // Backing off releases the bumper.
  drive(sim, -0.2, 0.0, 1.0);
  EXPECT_FALSE(sim.bumpers()[kBumperCenter]);
  EXPECT_LT(sim.pose().x, 0.7);
}

TEST(Simulation, SideBumper) {
  // Wall ahead, robot heading 60 degrees to the right of it: contact on the left bumper.
  Simulation sim(wall_at(0.5), quiet_config(), Pose2D{0, 0, -M_PI / 3});
  bool left = false;
  for (int i = 0; i < 300; ++i) {
    if (i % 10 == 0) sim.command(0.3, 0.0);
    for (const auto& c : sim.step()) left |= c.bumper == kBumperLeft && c.pressed;
  }
  EXPECT_TRUE(left);
}

TEST(Simulation, RejectsStartInsideObstacle) {
  EXPECT_THROW(Simulation(wall_at(1.0), quiet_config(), Pose2D{1.5, 0, 0}), std::invalid_argument);
}

TEST(Simulation, FindsTheNearestFreePosition) {
  const World world(testing_helpers::box_world(Pose2D{}, 2.0, 2.0));  // x, y in [-1, 1]
  Eigen::Vector2d found;
  ASSERT_TRUE(find_free_position(world, RobotGeometry{}, Eigen::Vector2d(0.5, 0.0), 5.0, &found));
  EXPECT_NEAR(found.y(), 0.0, 1e-9);
  EXPECT_GT(found.x(), 1.18);
  EXPECT_LT(found.x(), 1.26);
  EXPECT_FALSE(world.cylinder_collides(found, 0.18, 0.4, 0.02));
  // Already free: stays.
  ASSERT_TRUE(find_free_position(world, RobotGeometry{}, Eigen::Vector2d(3.0, 3.0), 5.0, &found));
  EXPECT_EQ(found, Eigen::Vector2d(3.0, 3.0));
}
