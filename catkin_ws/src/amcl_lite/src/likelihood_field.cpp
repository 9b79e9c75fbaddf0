#include "amcl_lite/likelihood_field.h"

#include <cmath>
#include <cstdio>
#include <queue>
#include <stdexcept>

namespace amcl_lite {

LikelihoodField::LikelihoodField(const GridMap& map, double max_dist, int occupied_threshold,
                                 int free_threshold)
    : map_(map), max_dist_(max_dist) {
  if (map.width <= 0 || map.height <= 0 || !(map.resolution > 0.0))
    throw std::invalid_argument("map must have a positive size and resolution");
  if (map.cells.size() != static_cast<size_t>(map.width) * map.height)
    throw std::invalid_argument("map cell count does not match width x height");
  if (!(max_dist > 0.0)) throw std::invalid_argument("laser_likelihood_max_dist must be > 0");
  const size_t n = map.cells.size();
  distance_.assign(n, static_cast<float>(max_dist));
  free_.assign(n, 0);
  // Brushfire from every obstacle cell, each cell remembering its nearest obstacle, so the
  // distance is Euclidean (as amcl's map_update_cspace) and the search stops at max_dist.
  struct Item {
    float d;
    int cell, source;
    bool operator>(const Item& o) const { return d > o.d; }
  };
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  for (size_t i = 0; i < n; ++i) {
    const int v = map.cells[i];
    if (v >= occupied_threshold) {
      distance_[i] = 0.0f;
      open.push({0.0f, static_cast<int>(i), static_cast<int>(i)});
    } else if (v >= 0 && v < free_threshold) {
      free_[i] = 1;
      free_cells_.emplace_back(map.origin_x + (i % map.width + 0.5) * map.resolution,
                               map.origin_y + (i / map.width + 0.5) * map.resolution);
    }
  }
  while (!open.empty()) {
    const Item it = open.top();
    open.pop();
    if (it.d > distance_[it.cell]) continue;
    const int r = it.cell / map.width, c = it.cell % map.width;
    const int sr = it.source / map.width, sc = it.source % map.width;
    for (int dr = -1; dr <= 1; ++dr) {
      for (int dc = -1; dc <= 1; ++dc) {
        const int nr = r + dr, nc = c + dc;
        if ((!dr && !dc) || nr < 0 || nc < 0 || nr >= map.height || nc >= map.width) continue;
        const int k = nr * map.width + nc;
        const float d = static_cast<float>(std::hypot(nr - sr, nc - sc) * map.resolution);
        if (d < distance_[k]) {
          distance_[k] = d;
          open.push({d, k, it.source});
        }
      }
    }
  }
}

bool LikelihoodField::cellOf(double x, double y, int* col, int* row) const {
  // Compared as doubles before the cast: a particle drawn from an initial pose with a huge
  // variance (1e300) or a NaN would overflow int, which is undefined behaviour.
  const double c = std::floor((x - map_.origin_x) / map_.resolution);
  const double r = std::floor((y - map_.origin_y) / map_.resolution);
  if (!(c >= 0 && r >= 0 && c < map_.width && r < map_.height)) return false;
  *col = static_cast<int>(c);
  *row = static_cast<int>(r);
  return true;
}

double LikelihoodField::distance(double x, double y) const {
  int c, r;
  if (!cellOf(x, y, &c, &r)) return max_dist_;
  return distance_[static_cast<size_t>(r) * map_.width + c];
}

bool LikelihoodField::isFree(double x, double y) const {
  int c, r;
  return cellOf(x, y, &c, &r) && free_[static_cast<size_t>(r) * map_.width + c];
}

std::string initialPoseProblem(const GridMap& map, double x, double y, double cov_xx, double cov_yy) {
  const double x1 = map.origin_x + map.width * map.resolution;
  const double y1 = map.origin_y + map.height * map.resolution;
  const double diagonal = std::hypot(map.width * map.resolution, map.height * map.resolution);
  char text[320];
  if (!(x >= map.origin_x && x <= x1 && y >= map.origin_y && y <= y1)) {
    std::snprintf(text, sizeof text, "the initial pose (%g, %g) is off the map (x %.2f to %.2f, y %.2f to %.2f)", x, y,
                  map.origin_x, x1, map.origin_y, y1);
    return text;
  }
  const double sx = std::sqrt(cov_xx), sy = std::sqrt(cov_yy);
  if (!(sx <= diagonal && sy <= diagonal)) {
    std::snprintf(text, sizeof text,
                  "the initial pose's spread (standard deviations %g, %g m) is wider than the map's diagonal (%.1f m)", sx, sy,
                  diagonal);
    return text;
  }
  return "";
}

}  // namespace amcl_lite
