#include "bullet_turtlebot/occupancy_export.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rosbook_env/map_files.h"

namespace bullet_turtlebot {
namespace {

bool contains(const Solid& s, double x, double y) {
  const double dx = x - s.center.x(), dy = y - s.center.y();
  if (s.kind == Solid::kCylinder) return dx * dx + dy * dy <= s.half.x() * s.half.x();
  const double c = std::cos(s.yaw), sn = std::sin(s.yaw);
  const double lx = c * dx + sn * dy, ly = -sn * dx + c * dy;
  return std::abs(lx) <= s.half.x() && std::abs(ly) <= s.half.y();
}

}  // namespace

MapImage rasterize_world(const World& world, double resolution, double margin, double min_height) {
  if (!(resolution > 0) || !std::isfinite(resolution)) throw std::invalid_argument("resolution must be > 0");
  if (!(margin >= 0) || !std::isfinite(margin)) throw std::invalid_argument("margin must be a finite number >= 0");
  if (std::isnan(min_height)) throw std::invalid_argument("min_height must be a number");
  MapImage map;
  map.resolution = resolution;
  const Eigen::Vector2d lo = world.min_corner() - Eigen::Vector2d::Constant(margin);
  const Eigen::Vector2d hi = world.max_corner() + Eigen::Vector2d::Constant(margin);
  // Sizes in double first: a huge margin or a tiny resolution must not overflow the int cast.
  const double columns = std::max(1.0, std::ceil((hi.x() - lo.x()) / resolution));
  const double rows = std::max(1.0, std::ceil((hi.y() - lo.y()) / resolution));
  if (!(columns * rows <= 400.0 * 1000 * 1000)) {
    throw std::invalid_argument("map would be too large at this resolution and margin");
  }
  const int width = static_cast<int>(columns), height = static_cast<int>(rows);
  map.origin = Pose2D{lo.x(), lo.y(), 0.0};
  map.image.width = width;
  map.image.height = height;
  map.image.pixels.assign(static_cast<size_t>(width) * height, 254);
  for (const Solid& s : world.solids()) {
    if (s.center.z() + s.half.z() <= min_height) continue;
    // Only the cells under the solid's bounding circle can be inside it.
    const double reach = std::hypot(s.half.x(), s.half.y());
    const int i0 = std::max(0, static_cast<int>(std::floor((s.center.x() - reach - lo.x()) / resolution)));
    const int i1 = std::min(width - 1, static_cast<int>(std::floor((s.center.x() + reach - lo.x()) / resolution)));
    const int j0 = std::max(0, static_cast<int>(std::floor((s.center.y() - reach - lo.y()) / resolution)));
    const int j1 = std::min(height - 1, static_cast<int>(std::floor((s.center.y() + reach - lo.y()) / resolution)));
    for (int j = j0; j <= j1; ++j) {
      const double y = lo.y() + (j + 0.5) * resolution;
      for (int i = i0; i <= i1; ++i) {
        const double x = lo.x() + (i + 0.5) * resolution;
        if (contains(s, x, y)) map.image.pixels[static_cast<size_t>(height - 1 - j) * width + i] = 0;
      }
    }
  }
  return map;
}

void write_map(const MapImage& map, const std::string& base_name) {
  rosbook_env::MapImage file;
  file.width = map.image.width;
  file.height = map.image.height;
  file.pixels = map.image.pixels;
  file.resolution = map.resolution;
  file.origin_x = map.origin.x;
  file.origin_y = map.origin.y;
  file.origin_yaw = map.origin.yaw;
  rosbook_env::write_map_files(base_name, file, "CREATOR: bullet_turtlebot");
}

}  // namespace bullet_turtlebot
