#include "bullet_turtlebot/sensors.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bullet_turtlebot {
namespace {

// Unit ray direction in the world for a pixel of a level camera with heading `yaw`.
// The optical frame looks along +x of the camera frame: image right = -y, image down = -z.
struct Intrinsics {
  double f, cx, cy;
  explicit Intrinsics(const CameraConfig& camera) : f(camera.focal()), cx(camera.cx()), cy(camera.cy()) {}
};

Eigen::Vector3d pixel_ray(const Intrinsics& k, double cos_yaw, double sin_yaw, int u, int v, double* norm) {
  const double right = (u - k.cx) / k.f;
  const double down = (v - k.cy) / k.f;
  const Eigen::Vector3d body(1.0, -right, -down);
  *norm = body.norm();
  return Eigen::Vector3d(cos_yaw * body.x() - sin_yaw * body.y(), sin_yaw * body.x() + cos_yaw * body.y(),
                         body.z()) /
         *norm;
}

// Length of the longest pixel ray per unit of depth (the image corner).
double corner_norm(const CameraConfig& camera) {
  const double f = camera.focal();
  return Eigen::Vector3d(1.0, camera.cx() / f, camera.cy() / f).norm();
}

}  // namespace

void scan_ranges(const World& world, const LaserConfig& config, const SensorPose& pose, std::mt19937_64* rng,
                 std::vector<float>* ranges) {
  ranges->resize(static_cast<size_t>(config.samples));
  std::normal_distribution<double> gauss(0.0, 1.0);
  const bool noisy = rng != nullptr && (config.noise > 0 || config.noise_quadratic > 0);
  const RayFan fan(world, pose.position, config.range_max, pose.yaw, config.fov / 2 + 1e-3);
  // Beam directions relative to the sensor are fixed: compute them once per configuration.
  thread_local std::vector<Eigen::Vector2d> beams;
  thread_local double beams_fov = -1;
  if (beams.size() != static_cast<size_t>(config.samples) || beams_fov != config.fov) {
    beams.resize(static_cast<size_t>(config.samples));
    for (int i = 0; i < config.samples; ++i) {
      const double a = config.angle_min() + i * config.angle_increment();
      beams[static_cast<size_t>(i)] = Eigen::Vector2d(std::cos(a), std::sin(a));
    }
    beams_fov = config.fov;
  }
  const double cy = std::cos(pose.yaw), sy = std::sin(pose.yaw);
  for (int i = 0; i < config.samples; ++i) {
    const Eigen::Vector2d& b = beams[static_cast<size_t>(i)];
    const Eigen::Vector3d dir(cy * b.x() - sy * b.y(), sy * b.x() + cy * b.y(), 0.0);
    const int bin = fan.bin_of(pose.yaw + config.angle_min() + i * config.angle_increment());
    RayHit hit;
    float value;
    if (!fan.cast_in_bin(bin, dir, config.range_max, &hit, false)) {
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
  const RayFan fan(world, pose.position, camera.depth_max * corner_norm(camera), pose.yaw, camera.hfov / 2 + 1e-3);
  const Intrinsics k(camera);
  for (int u = 0; u < camera.width; ++u) {
    // Every pixel of a column of a level camera has the same azimuth.
    const int bin = fan.bin_of(pose.yaw + std::atan2(-(u - k.cx) / k.f, 1.0));
    for (int v = 0; v < camera.height; ++v) {
      double norm;
      const Eigen::Vector3d dir = pixel_ray(k, c, s, u, v, &norm);
      RayHit hit;
      float value = nan;
      if (fan.cast_in_bin(bin, dir, camera.depth_max * norm, &hit)) {
        const double z = hit.distance / norm;
        if (z >= camera.depth_min && z <= camera.depth_max) value = static_cast<float>(z);
      }
      (*depth)[static_cast<size_t>(v) * camera.width + u] = value;
    }
  }
}

void render_rgb(const World& world, const CameraConfig& camera, const SensorPose& pose,
                std::vector<std::uint8_t>* rgb) {
  rgb->resize(static_cast<size_t>(camera.width) * camera.height * 3);
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  const Eigen::Vector3d light = Eigen::Vector3d(0.4, 0.25, 0.88).normalized();
  const double view_distance = 30.0;
  const RayFan fan(world, pose.position, view_distance, pose.yaw, camera.hfov / 2 + 1e-3);
  const Intrinsics intrinsics(camera);
  for (int u = 0; u < camera.width; ++u) {
    const int bin = fan.bin_of(pose.yaw + std::atan2(-(u - intrinsics.cx) / intrinsics.f, 1.0));
    for (int v = 0; v < camera.height; ++v) {
      const size_t k = (static_cast<size_t>(v) * camera.width + u) * 3;
      double norm;
      const Eigen::Vector3d dir = pixel_ray(intrinsics, c, s, u, v, &norm);
      RayHit hit;
      double r = 0.72, g = 0.82, b = 0.95;  // sky
      if (fan.cast_in_bin(bin, dir, view_distance, &hit)) {
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
