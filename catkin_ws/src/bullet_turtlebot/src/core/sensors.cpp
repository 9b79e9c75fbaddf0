#include "bullet_turtlebot/sensors.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bullet_turtlebot {
namespace {

struct Intrinsics {
  double f, cx, cy;
  explicit Intrinsics(const CameraConfig& camera) : f(camera.focal()), cx(camera.cx()), cy(camera.cy()) {}
};

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
    const int bin = fan.bin_of_relative(config.angle_min() + i * config.angle_increment());
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

namespace {

struct ColumnHit {
  double s;  // horizontal distance from the camera
  Eigen::Vector3d normal;
  int solid;  // -1 floor
};

// First surface along a pixel ray of a column: height z(s) = z0 + slope * s over the
// horizontal distance s; spans sorted by s_in; the floor is z = 0.
bool resolve_column(const std::vector<Span>& spans, double z0, double slope, double max_s, ColumnHit* hit) {
  double best = max_s;
  bool found = false;
  for (const Span& span : spans) {
    if (span.s_in >= best) break;
    const double z_in = z0 + slope * span.s_in;
    if (z_in >= span.z_lo && z_in <= span.z_hi) {  // its side, and nothing later can be nearer
      *hit = ColumnHit{span.s_in, Eigen::Vector3d(span.side_normal.x(), span.side_normal.y(), 0.0), span.solid};
      return true;
    }
    // Over (or under) it at its near side: the ray may still come down on its top.
    const double z_face = slope < 0 && z_in > span.z_hi ? span.z_hi : (slope > 0 && z_in < span.z_lo ? span.z_lo : NAN);
    if (std::isnan(z_face)) continue;
    const double s_face = (z_face - z0) / slope;
    if (s_face <= span.s_out && s_face < best) {
      best = s_face;
      *hit = ColumnHit{s_face, Eigen::Vector3d(0, 0, z_face == span.z_hi ? 1.0 : -1.0), span.solid};
      found = true;
    }
  }
  if (slope < 0 && z0 > 0) {
    const double s_floor = -z0 / slope;
    if (s_floor < best) {
      *hit = ColumnHit{s_floor, Eigen::Vector3d::UnitZ(), -1};
      found = true;
    }
  }
  return found;
}

Color floor_color(const Eigen::Vector3d& p) {
  const bool dark = (static_cast<long>(std::floor(p.x())) + static_cast<long>(std::floor(p.y()))) & 1;
  return dark ? Color{0.55f, 0.55f, 0.5f} : Color{0.68f, 0.68f, 0.62f};
}

}  // namespace

// Both renderers work column by column: a level camera's column is one vertical plane, so the
// solids it crosses (spans) are found once, then each pixel is resolved from them.
void render_depth(const World& world, const CameraConfig& camera, const SensorPose& pose,
                  std::vector<float>* depth) {
  depth->resize(static_cast<size_t>(camera.width) * camera.height);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const Intrinsics k(camera);
  const double max_right = std::max(k.cx, camera.width - 1 - k.cx) / k.f;
  const RayFan fan(world, pose.position, camera.depth_max * std::sqrt(1 + max_right * max_right), pose.yaw,
                   camera.hfov / 2 + 1e-3);
  std::vector<Span> spans;
  for (int u = 0; u < camera.width; ++u) {
    const double right = (u - k.cx) / k.f;
    const double h = std::sqrt(1 + right * right);  // horizontal length per unit depth
    const double azimuth = pose.yaw + std::atan2(-right, 1.0);
    const Eigen::Vector2d dir(std::cos(azimuth), std::sin(azimuth));
    const double max_s = camera.depth_max * h;
    fan.column_spans(fan.bin_of(azimuth), dir, max_s, &spans);
    for (int v = 0; v < camera.height; ++v) {
      const double slope = -(v - k.cy) / k.f / h;
      ColumnHit hit;
      float value = nan;
      if (resolve_column(spans, pose.position.z(), slope, max_s, &hit)) {
        const double z = hit.s / h;
        if (z >= camera.depth_min && z <= camera.depth_max) value = static_cast<float>(z);
      }
      (*depth)[static_cast<size_t>(v) * camera.width + u] = value;
    }
  }
}

void render_rgb(const World& world, const CameraConfig& camera, const SensorPose& pose,
                std::vector<std::uint8_t>* rgb) {
  rgb->resize(static_cast<size_t>(camera.width) * camera.height * 3);
  const Eigen::Vector3d light = Eigen::Vector3d(0.4, 0.25, 0.88).normalized();
  const double view_distance = 30.0;
  const Intrinsics k(camera);
  const RayFan fan(world, pose.position, view_distance, pose.yaw, camera.hfov / 2 + 1e-3);
  const auto& solids = world.solids();
  std::vector<Span> spans;
  for (int u = 0; u < camera.width; ++u) {
    const double right = (u - k.cx) / k.f;
    const double h = std::sqrt(1 + right * right);
    const double azimuth = pose.yaw + std::atan2(-right, 1.0);
    const Eigen::Vector2d dir(std::cos(azimuth), std::sin(azimuth));
    fan.column_spans(fan.bin_of(azimuth), dir, view_distance, &spans);
    for (int v = 0; v < camera.height; ++v) {
      const size_t i = (static_cast<size_t>(v) * camera.width + u) * 3;
      const double down = (v - k.cy) / k.f;
      const double slope = -down / h;
      double r = 0.72, g = 0.82, b = 0.95;  // sky
      ColumnHit hit;
      if (resolve_column(spans, pose.position.z(), slope, view_distance, &hit)) {
        const Eigen::Vector3d p(pose.position.x() + hit.s * dir.x(), pose.position.y() + hit.s * dir.y(),
                                pose.position.z() + slope * hit.s);
        const Color color = hit.solid < 0 ? floor_color(p) : solids[static_cast<size_t>(hit.solid)].color;
        const double distance = hit.s * std::sqrt(1 + slope * slope);
        // Lambert with both sides lit a little, plus a slight fade with distance.
        const double shade = 0.45 + 0.55 * std::abs(hit.normal.dot(light));
        const double fade = 1.0 / (1.0 + 0.02 * distance);
        r = color.r * shade * fade;
        g = color.g * shade * fade;
        b = color.b * shade * fade;
      }
      (*rgb)[i] = static_cast<std::uint8_t>(std::clamp(r, 0.0, 1.0) * 255.0 + 0.5);
      (*rgb)[i + 1] = static_cast<std::uint8_t>(std::clamp(g, 0.0, 1.0) * 255.0 + 0.5);
      (*rgb)[i + 2] = static_cast<std::uint8_t>(std::clamp(b, 0.0, 1.0) * 255.0 + 0.5);
    }
  }
}

}  // namespace bullet_turtlebot
