// Kinect emulation by ray casting: a planar fake laser made from the depth camera's middle
// row geometry, a depth image (REP 118), and a shaded colour view.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <random>
#include <vector>

#include "bullet_turtlebot/world.hpp"

namespace bullet_turtlebot {

// Camera/laser origin in the world: position and heading (the Turtlebot's Kinect is level).
struct SensorPose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double yaw = 0.0;
};

struct LaserConfig {
  int samples = 640;
  double fov = 58.0 * M_PI / 180.0;  // symmetric about +x
  double range_min = 0.45;
  double range_max = 8.0;
  double noise = 0.0;            // sigma, m
  double noise_quadratic = 0.0;  // sigma grows with range^2 (Kinect-like), 1/m

  double angle_min() const { return -fov / 2; }
  double angle_increment() const { return samples > 1 ? fov / (samples - 1) : 0.0; }
};

// REP 117: +inf for no return within range_max, -inf for a return closer than range_min.
void scan_ranges(const World& world, const LaserConfig& config, const SensorPose& pose,
                 std::mt19937_64* rng, std::vector<float>* ranges);

struct CameraConfig {
  int width = 640;
  int height = 480;
  double hfov = 58.0 * M_PI / 180.0;
  double depth_min = 0.45;
  double depth_max = 10.0;

  double focal() const { return (width / 2.0) / std::tan(hfov / 2.0); }
  double cx() const { return (width - 1) / 2.0; }
  double cy() const { return (height - 1) / 2.0; }
};

// Depth along the optical axis per pixel (metres, row-major), NaN where nothing is seen
// between depth_min and depth_max (REP 118).
void render_depth(const World& world, const CameraConfig& camera, const SensorPose& pose,
                  std::vector<float>* depth);

// rgb8, row-major: solids shaded by their colour and a fixed light, a tiled floor, a sky.
void render_rgb(const World& world, const CameraConfig& camera, const SensorPose& pose,
                std::vector<std::uint8_t>* rgb);

}  // namespace bullet_turtlebot
