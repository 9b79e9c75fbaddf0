#include <gtest/gtest.h>

#include <cmath>

#include "bullet_turtlebot/sensors.hpp"
#include "test_helpers.hpp"

using namespace bullet_turtlebot;

TEST(Scan, MiddleBeamReadsWallDistance) {
  World world(testing_helpers::wall_world(2.0));
  LaserConfig config;
  SensorPose pose;
  pose.position = Eigen::Vector3d(0, 0, 0.3);
  std::vector<float> ranges;
  scan_ranges(world, config, pose, nullptr, &ranges);
  ASSERT_EQ(ranges.size(), 640u);
  EXPECT_NEAR(ranges[319], 2.0, 0.001);
  EXPECT_NEAR(ranges[320], 2.0, 0.001);
  // Symmetric about +x: first and last beams at -/+ 29 degrees.
  EXPECT_NEAR(config.angle_min(), -29.0 * M_PI / 180, 1e-12);
  EXPECT_NEAR(config.angle_min() + 639 * config.angle_increment(), 29.0 * M_PI / 180, 1e-12);
  EXPECT_NEAR(ranges[0], 2.0 / std::cos(29.0 * M_PI / 180), 0.001);
}

TEST(Scan, Rep117InfinitiesAndNoise) {
  World world(testing_helpers::wall_world(2.0));
  LaserConfig config;
  SensorPose pose;
  pose.position = Eigen::Vector3d(0, 0, 0.3);
  pose.yaw = M_PI;  // facing away: nothing within range
  std::vector<float> ranges;
  scan_ranges(world, config, pose, nullptr, &ranges);
  for (float r : ranges) EXPECT_TRUE(std::isinf(r) && r > 0);
  pose.yaw = 0;
  pose.position.x() = 1.7;  // wall 0.3 m away, closer than range_min
  scan_ranges(world, config, pose, nullptr, &ranges);
  EXPECT_TRUE(std::isinf(ranges[320]) && ranges[320] < 0);
  pose.position.x() = 0;
  config.noise = 0.01;
  std::mt19937_64 a(5), b(5);
  std::vector<float> ra, rb;
  scan_ranges(world, config, pose, &a, &ra);
  scan_ranges(world, config, pose, &b, &rb);
  EXPECT_EQ(ra, rb);
  EXPECT_NE(ra[320], 2.0f);
  EXPECT_NEAR(ra[320], 2.0, 0.06);
}

TEST(DepthCamera, CentreDepthFloorAndNaN) {
  World world(testing_helpers::wall_world(2.0));
  CameraConfig camera;
  camera.width = 64;
  camera.height = 48;
  SensorPose pose;
  pose.position = Eigen::Vector3d(0, 0, 0.3);
  std::vector<float> depth;
  render_depth(world, camera, pose, &depth);
  ASSERT_EQ(depth.size(), 64u * 48u);
  // Depth along the optical axis: the whole wall reads 2.0 wherever it is seen.
  EXPECT_NEAR(depth[24 * 64 + 32], 2.0, 1e-4);
  EXPECT_NEAR(depth[24 * 64 + 0], 2.0, 1e-4);
  // Top rows see over the 1 m wall: nothing, NaN (REP 118).
  EXPECT_TRUE(std::isnan(depth[0 * 64 + 32]));
  // Bottom row sees the floor nearer than the wall.
  EXPECT_LT(depth[47 * 64 + 32], 2.0);
  std::vector<std::uint8_t> rgb;
  render_rgb(world, camera, pose, &rgb);
  ASSERT_EQ(rgb.size(), 64u * 48u * 3u);
  EXPECT_NE(rgb[0], rgb[(24 * 64 + 32) * 3]);  // sky differs from wall
}
