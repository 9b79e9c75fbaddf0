#include "bullet_turtlebot/sensors.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bullet_turtlebot {
namespace {

// Unit ray direction in the world for a pixel of a level camera with heading `yaw`.
// The optical frame looks along +x of the camera frame: image right = -y, image down = -z.
Eigen::Vector3d pixel_ray(const CameraConfig& camera, double cos_yaw, double sin_yaw, int u, int v,
                          double* norm) {
  const double f = camera.focal();
  const double right = (u - camera.cx()) / f;
  const double down = (v - camera.cy()) / f;
  const Eigen::Vector3d body(1.0, -right, -down);
  *norm = body.norm();
  return Eigen::Vector3d(cos_yaw * body.x() - sin_yaw * body.y(), sin_yaw * body.x() + cos_yaw * body.y(),
                         body.z()) /
         *norm;
}

}  // namespace

void scan_ranges(const World& world, const LaserConfig& config, const SensorPose& pose, std::mt19937_64* rng,
                 std::vector<float>* ranges) {
  ranges->resize(static_cast<size_t>(config.samples));
  std::normal_distribution<double> gauss(0.0, 1.0);
  const bool noisy = rng != nullptr && (config.noise > 0 || config.noise_quadratic > 0);
  for (int i = 0; i < config.samples; ++i) {
    const double angle = pose.yaw + config.angle_min() + i * config.angle_increment();
    const Eigen::Vector3d dir(std::cos(angle), std::sin(angle), 0.0);
    RayHit hit;
    float value;
    if (!world.raycast(pose.position, dir, config.range_max, &hit, false)) {
      value = std::numeric_limits<float>::infinity();
    } else if (hit.distance < config.range_min) {
      value = -std::numeric_limits<float>::infinity();
    } else {
      double r = hit.distance;
      if (noisy) {
        r += (config.noise + config.noise_quadratic * r * r) * gauss(*rng);
        r = std::clamp(r, config.range_min, config.range_max);
      }
      value = static_cast<float>(r);
    }
    (*ranges)[static_cast<size_t>(i)] = value;
  }
}

void render_depth(const World& world, const CameraConfig& camera, const SensorPose& pose,
                  std::vector<float>* depth) {
  depth->resize(static_cast<size_t>(camera.width) * camera.height);
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  size_t k = 0;
  for (int v = 0; v < camera.height; ++v) {
    for (int u = 0; u < camera.width; ++u, ++k) {
      double norm;
      const Eigen::Vector3d dir = pixel_ray(camera, c, s, u, v, &norm);
      RayHit hit;
      float value = nan;
      if (world.raycast(pose.position, dir, camera.depth_max * norm, &hit)) {
        const double z = hit.distance / norm;
        if (z >= camera.depth_min && z <= camera.depth_max) value = static_cast<float>(z);
      }
      (*depth)[k] = value;
    }
  }
}

void render_rgb(const World& world, const CameraConfig& camera, const SensorPose& pose,
                std::vector<std::uint8_t>* rgb) {
  rgb->resize(static_cast<size_t>(camera.width) * camera.height * 3);
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  const Eigen::Vector3d light = Eigen::Vector3d(0.4, 0.25, 0.88).normalized();
  const double view_distance = 30.0;
  size_t k = 0;
  for (int v = 0; v < camera.height; ++v) {
    for (int u = 0; u < camera.width; ++u, k += 3) {
      double norm;
      const Eigen::Vector3d dir = pixel_ray(camera, c, s, u, v, &norm);
      RayHit hit;
      double r = 0.72, g = 0.82, b = 0.95;  // sky
      if (world.raycast(pose.position, dir, view_distance, &hit)) {
        // Lambert with both sides lit a little, plus a slight fade with distance.
        const double shade = 0.45 + 0.55 * std::abs(hit.normal.dot(light));
        const double fade = 1.0 / (1.0 + 0.02 * hit.distance);
        r = hit.color.r * shade * fade;
        g = hit.color.g * shade * fade;
        b = hit.color.b * shade * fade;
      }
      (*rgb)[k] = static_cast<std::uint8_t>(std::clamp(r, 0.0, 1.0) * 255.0 + 0.5);
      (*rgb)[k + 1] = static_cast<std::uint8_t>(std::clamp(g, 0.0, 1.0) * 255.0 + 0.5);
      (*rgb)[k + 2] = static_cast<std::uint8_t>(std::clamp(b, 0.0, 1.0) * 255.0 + 0.5);
    }
  }
}

}  // namespace bullet_turtlebot
