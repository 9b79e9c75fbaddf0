#include <gtest/gtest.h>

#include <cmath>

#include "bullet_turtlebot/world.hpp"
#include "test_helpers.hpp"

using namespace bullet_turtlebot;

TEST(Raycast, WallStraightAhead) {
  World world(testing_helpers::wall_world(2.0));
  RayHit hit;
  ASSERT_TRUE(world.raycast(Eigen::Vector3d(0, 0, 0.3), Eigen::Vector3d::UnitX(), 8.0, &hit, false));
  EXPECT_NEAR(hit.distance, 2.0, 1e-9);
  EXPECT_NEAR(hit.normal.x(), -1.0, 1e-9);
  EXPECT_EQ(hit.solid, 0);
}

TEST(Raycast, SlantedRayAndMaxRange) {
  World world(testing_helpers::wall_world(2.0));
  RayHit hit;
  const double a = 0.4;
  ASSERT_TRUE(world.raycast(Eigen::Vector3d(0, 0, 0.3), Eigen::Vector3d(std::cos(a), std::sin(a), 0), 8.0, &hit, false));
  EXPECT_NEAR(hit.distance, 2.0 / std::cos(a), 1e-9);
  EXPECT_FALSE(world.raycast(Eigen::Vector3d(0, 0, 0.3), Eigen::Vector3d::UnitX(), 1.9, &hit, false));
  EXPECT_FALSE(world.raycast(Eigen::Vector3d(0, 0, 0.3), -Eigen::Vector3d::UnitX(), 8.0, &hit, false));
}

TEST(Raycast, OverLowWallAndFloor) {
  World world(testing_helpers::wall_world(2.0, 0.2));
  RayHit hit;
  EXPECT_FALSE(world.raycast(Eigen::Vector3d(0, 0, 0.3), Eigen::Vector3d::UnitX(), 8.0, &hit, false));
  // Looking down 45 degrees from 0.3 m: the floor at 0.3 m.
  const Eigen::Vector3d down = Eigen::Vector3d(1, 0, -1).normalized();
  ASSERT_TRUE(world.raycast(Eigen::Vector3d(0, 0, 0.3), down, 8.0, &hit, true));
  EXPECT_EQ(hit.solid, -1);
  EXPECT_NEAR(hit.distance, 0.3 * std::sqrt(2.0), 1e-9);
}

TEST(Raycast, RotatedBoxAndCylinder) {
  WorldSpec spec;
  BoxSpec box;
  box.pose = Pose2D{3.0, 0.0, M_PI / 4};
  box.size_x = box.size_y = std::sqrt(2.0);  // a diamond whose near corner is at x = 2
  box.size_z = 1.0;
  spec.boxes.push_back(box);
  CylinderSpec cyl;
  cyl.x = 0.0;
  cyl.y = 3.0;
  cyl.radius = 0.5;
  cyl.height = 1.0;
  spec.cylinders.push_back(cyl);
  World world(spec);
  RayHit hit;
  ASSERT_TRUE(world.raycast(Eigen::Vector3d(0, 0, 0.5), Eigen::Vector3d::UnitX(), 8.0, &hit, false));
  EXPECT_NEAR(hit.distance, 2.0, 1e-9);
  ASSERT_TRUE(world.raycast(Eigen::Vector3d(0, 0, 0.5), Eigen::Vector3d::UnitY(), 8.0, &hit, false));
  EXPECT_NEAR(hit.distance, 2.5, 1e-9);
  EXPECT_NEAR(hit.normal.y(), -1.0, 1e-9);
  // From above, the cylinder's top cap.
  ASSERT_TRUE(world.raycast(Eigen::Vector3d(0, 3, 2.0), -Eigen::Vector3d::UnitZ(), 8.0, &hit, false));
  EXPECT_NEAR(hit.distance, 1.0, 1e-9);
}

TEST(Raycast, GridWallsFromImage) {
  // 10 x 10 cells of 0.1 m, origin (-0.5, -0.5): the right-most column is occupied, i.e.
  // a wall whose face is at x = 0.4.
  WorldSpec spec;
  spec.grid.width = 10;
  spec.grid.height = 10;
  spec.grid.resolution = 0.1;
  spec.grid.origin = Pose2D{-0.5, -0.5, 0.0};
  spec.grid.occupied.assign(100, 0);
  for (int row = 0; row < 10; ++row) spec.grid.occupied[row * 10 + 9] = 1;
  // Top-left cell (row 0 = top = high y).
  spec.grid.occupied[0] = 1;
  World world(spec);
  EXPECT_EQ(world.solids().size(), 2u);
  RayHit hit;
  ASSERT_TRUE(world.raycast(Eigen::Vector3d(0, 0, 0.3), Eigen::Vector3d::UnitX(), 8.0, &hit, false));
  EXPECT_NEAR(hit.distance, 0.4, 1e-6);
  // The top-left cell spans x in [-0.5, -0.4], y in [0.4, 0.5].
  ASSERT_TRUE(world.raycast(Eigen::Vector3d(-0.45, 0, 0.3), Eigen::Vector3d::UnitY(), 8.0, &hit, false));
  EXPECT_NEAR(hit.distance, 0.4, 1e-6);
}

TEST(Sweep, StopsAtWallAndBacksAway) {
  World world(testing_helpers::wall_world(2.0));
  // Radius 0.18: contact when the centre reaches x = 1.82.
  SweepResult s = world.sweep_cylinder(Eigen::Vector2d(1.5, 0), Eigen::Vector2d(2.5, 0), 0.18, 0.4, 0.02);
  ASSERT_TRUE(s.hit);
  EXPECT_NEAR(1.5 + s.fraction * 1.0, 1.82, 0.01);
  EXPECT_LT(s.normal.x(), -0.9);
  // Touching the wall, moving away is free.
  s = world.sweep_cylinder(Eigen::Vector2d(1.819, 0), Eigen::Vector2d(1.5, 0), 0.18, 0.4, 0.02);
  EXPECT_FALSE(s.hit);
  // Sliding along it is free too.
  s = world.sweep_cylinder(Eigen::Vector2d(1.815, 0), Eigen::Vector2d(1.815, 1.0), 0.18, 0.4, 0.02);
  EXPECT_FALSE(s.hit);
  EXPECT_TRUE(world.cylinder_collides(Eigen::Vector2d(1.9, 0), 0.18, 0.4, 0.02));
  EXPECT_FALSE(world.cylinder_collides(Eigen::Vector2d(1.5, 0), 0.18, 0.4, 0.02));
}

TEST(Sweep, NoTunnellingThroughThinWall) {
  World world(testing_helpers::box_world(Pose2D{1.0, 0.0, 0.0}, 0.02, 4.0));
  const SweepResult s = world.sweep_cylinder(Eigen::Vector2d(0, 0), Eigen::Vector2d(3.0, 0), 0.18, 0.4, 0.02);
  ASSERT_TRUE(s.hit);
  EXPECT_NEAR(s.fraction * 3.0, 0.99 - 0.18, 0.01);
}
