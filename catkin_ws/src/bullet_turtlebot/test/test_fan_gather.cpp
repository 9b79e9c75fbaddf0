// RayFan gathers only the solids its wedge can reach (bounding box of the sector, then a
// bounding-circle test). These tests compare its rays with a brute-force cast over every
// solid of the shipped worlds and of the Willow Garage plan (thousands of wall boxes), from
// random free poses, for a scan-like fan and for fans wider than a half-plane.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "bullet_turtlebot/world.hpp"
#include "bullet_turtlebot/world_spec.hpp"

namespace bt = bullet_turtlebot;

namespace {

// The reference: every solid tested, the floor last (what World::raycast computes).
bool brute_force(const bt::World& world, const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                 double max_distance, bt::RayHit* hit) {
  double best = max_distance;
  int best_index = -1;
  Eigen::Vector3d best_normal;
  for (size_t i = 0; i < world.solids().size(); ++i) {
    double t;
    Eigen::Vector3d n;
    if (bt::intersect_solid(world.solids()[i], origin, dir, best, &t, &n) && t < best) {
      best = t;
      best_index = static_cast<int>(i);
      best_normal = n;
    }
  }
  bool found = best_index >= 0;
  if (found) {
    hit->distance = best;
    hit->normal = best_normal;
    hit->solid = best_index;
  }
  if (bt::intersect_floor(origin, dir, best, hit)) found = true;
  return found;
}

std::vector<std::string> world_files() {
  std::vector<std::string> files;
  for (const char* name : {"playground", "maze", "office", "hospital", "warehouse", "ring", "lab"}) {
    files.push_back(std::string(WORLDS_DIR) + "/" + name + ".yaml");
  }
  if (std::ifstream(WILLOW_PGM).good()) {
    const std::string yaml = ::testing::TempDir() + "/willow_fan_gather.yaml";
    std::ofstream(yaml) << "image: " << WILLOW_PGM << "\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\n"
                        << "occupied_thresh: 0.65\nfree_thresh: 0.196\n";
    files.push_back(yaml);
  }
  return files;
}

void compare_fans(const std::string& file, double half_fov, double max_distance, double max_slope) {
  SCOPED_TRACE(file);
  const bt::World world(bt::load_world_file(file));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> ux(world.min_corner().x(), world.max_corner().x());
  std::uniform_real_distribution<double> uy(world.min_corner().y(), world.max_corner().y());
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int poses = 0, hits = 0;
  for (int attempt = 0; attempt < 2000 && poses < 25; ++attempt) {
    const Eigen::Vector2d at(ux(rng), uy(rng));
    if (world.cylinder_collides(at, 0.18, 0.4, 0.02)) continue;
    ++poses;
    const Eigen::Vector3d origin(at.x(), at.y(), 0.2972);
    const double yaw = M_PI * unit(rng);
    const bt::RayFan fan(world, origin, max_distance, yaw, half_fov);
    for (int k = 0; k < 200; ++k) {
      const double azimuth = yaw + half_fov * unit(rng);
      Eigen::Vector3d dir(std::cos(azimuth), std::sin(azimuth), max_slope * unit(rng));
      const double horizontal = max_distance / dir.head<2>().norm();
      dir.normalize();
      const double reach = std::min(max_distance, horizontal * dir.head<2>().norm());
      bt::RayHit expected, got;
      const bool want = brute_force(world, origin, dir, reach, &expected);
      ASSERT_EQ(want, fan.cast(dir, reach, &got)) << "at " << at.transpose() << " azimuth " << azimuth;
      if (!want) continue;
      ++hits;
      EXPECT_NEAR(expected.distance, got.distance, 1e-9);
      EXPECT_EQ(expected.solid, got.solid);
      EXPECT_NEAR((expected.normal - got.normal).norm(), 0.0, 1e-9);
    }
  }
  EXPECT_GE(poses, 10);
  EXPECT_GT(hits, 0);
}

}  // namespace

TEST(FanGather, ScanFanMatchesBruteForceOnShippedWorlds) {
  for (const std::string& file : world_files()) compare_fans(file, 29.0 * M_PI / 180 + 1e-3, 8.0, 0.0);
}

TEST(FanGather, CameraFanMatchesBruteForceOnShippedWorlds) {
  for (const std::string& file : world_files()) compare_fans(file, 0.52, 11.0, 0.4);
}

TEST(FanGather, WideFansMatchBruteForce) {
  for (const std::string& file : world_files()) {
    compare_fans(file, 1.7, 8.0, 0.2);
    compare_fans(file, M_PI, 8.0, 0.0);
  }
}
