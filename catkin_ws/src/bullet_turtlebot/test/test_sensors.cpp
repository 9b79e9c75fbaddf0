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

namespace {

// Reference depth for a pixel: one general ray cast (World::raycast) per pixel.
double reference_depth(const World& world, const CameraConfig& camera, const SensorPose& pose, int u, int v) {
  const double f = camera.focal();
  const double right = (u - camera.cx()) / f, down = (v - camera.cy()) / f;
  const Eigen::Vector3d body(1.0, -right, -down);
  const double norm = body.norm();
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  const Eigen::Vector3d dir = Eigen::Vector3d(c * body.x() - s * body.y(), s * body.x() + c * body.y(), body.z()) / norm;
  RayHit hit;
  if (!world.raycast(pose.position, dir, camera.depth_max * norm, &hit)) return NAN;
  const double z = hit.distance / norm;
  return z >= camera.depth_min && z <= camera.depth_max ? z : NAN;
}

}  // namespace

TEST(DepthCamera, ColumnRendererMatchesPerPixelRayCasts) {
  // Rotated boxes and cylinders of several heights (some below the camera: their tops show).
  WorldSpec spec;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> pos(-6.0, 6.0), size(0.1, 1.5), height(0.05, 1.5), yaw(-3.0, 3.0);
  for (int i = 0; i < 40; ++i) {
    BoxSpec box;
    box.pose = Pose2D{pos(rng), pos(rng), yaw(rng)};
    box.size_x = size(rng);
    box.size_y = size(rng);
    box.size_z = height(rng);
    if (std::hypot(box.pose.x, box.pose.y) < 1.5) continue;  // keep the camera clear
    spec.boxes.push_back(box);
    CylinderSpec cyl;
    cyl.x = pos(rng);
    cyl.y = pos(rng);
    cyl.radius = size(rng) / 3;
    cyl.height = height(rng);
    if (std::hypot(cyl.x, cyl.y) < 1.5) continue;
    spec.cylinders.push_back(cyl);
  }
  World world(spec);
  CameraConfig camera;
  camera.width = 160;
  camera.height = 120;
  for (const double heading : {0.0, 1.3, -2.4}) {
    SensorPose pose;
    pose.position = Eigen::Vector3d(0.1, -0.2, 0.2972);
    pose.yaw = heading;
    std::vector<float> depth;
    render_depth(world, camera, pose, &depth);
    int seen = 0;
    for (int v = 0; v < camera.height; ++v) {
      for (int u = 0; u < camera.width; ++u) {
        const double expected = reference_depth(world, camera, pose, u, v);
        const float got = depth[static_cast<size_t>(v) * camera.width + u];
        if (std::isnan(expected)) {
          EXPECT_TRUE(std::isnan(got)) << u << "," << v;
        } else {
          ++seen;
          EXPECT_NEAR(got, expected, 1e-4) << u << "," << v;
        }
      }
    }
    EXPECT_GT(seen, camera.width * camera.height / 3);
  }
}
