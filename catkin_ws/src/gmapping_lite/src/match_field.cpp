#include "gmapping_lite/match_field.h"

#include <cmath>

namespace gmapping_lite {

namespace {
// A cell is on a wall when its occupied neighbours' means lie along a line: the smaller
// spread is at most this share of the larger.
constexpr double kLineRatio = 0.1;
constexpr int kNormalWindow = 2;  // neighbours within this many cells shape the normal
constexpr int kMinNeighbours = 3;
}  // namespace

void MatchField::build(const GridMap& map, const CellIndex& min, const CellIndex& max,
                       double fullness, double radius) {
  const double res = map.resolution();
  x0_ = min.x;
  y0_ = min.y;
  w_ = std::max(0, max.x - min.x);
  h_ = std::max(0, max.y - min.y);
  inv_res_ = 1.0 / res;
  cap2_ = radius * radius;
  nearest_.assign(static_cast<std::size_t>(w_) * h_, -1);
  seeds_.clear();
  queue_.clear();
  // Seeds: occupied cells, each holding its own mean hit position. Walk the map patch by
  // patch (one lookup per patch, not per cell).
  const int n_patch = GridMap::kPatchSize;
  auto floorDiv = [n_patch](int v) {
    return v >= 0 ? v / n_patch : -((-v + n_patch - 1) / n_patch);
  };
  for (int py = floorDiv(y0_); py <= floorDiv(y0_ + h_ - 1); ++py) {
    for (int px = floorDiv(x0_); px <= floorDiv(x0_ + w_ - 1); ++px) {
      const Cell* cells = map.patchCells(px, py);
      if (!cells) continue;
      const int cx0 = std::max(px * n_patch, x0_), cx1 = std::min((px + 1) * n_patch, x0_ + w_);
      const int cy0 = std::max(py * n_patch, y0_), cy1 = std::min((py + 1) * n_patch, y0_ + h_);
      for (int cy = cy0; cy < cy1; ++cy) {
        for (int cx = cx0; cx < cx1; ++cx) {
          const Cell& c = cells[(cy - py * n_patch) * n_patch + (cx - px * n_patch)];
          if (!c.hits || c.occupancy() <= fullness) continue;
          const std::size_t k = static_cast<std::size_t>(cy - y0_) * w_ + (cx - x0_);
          nearest_[k] = static_cast<int32_t>(seeds_.size());
          seeds_.push_back({static_cast<float>((cx + 0.5) * res + c.sum_dx / c.hits),
                            static_cast<float>((cy + 0.5) * res + c.sum_dy / c.hits), 0.0f,
                            0.0f});
          queue_.push_back(static_cast<int32_t>(k));
        }
      }
    }
  }
  estimateNormals();
  // Brushfire: hand each cell the nearest seed of its neighbours, up to `radius`. Cells are
  // re-queued when a nearer seed arrives, so the result is the nearest seed in practice.
  auto dist2 = [&](int i, int j, const FieldSeed& s) {
    const double ex = (x0_ + i + 0.5) * res - s.mx, ey = (y0_ + j + 0.5) * res - s.my;
    return ex * ex + ey * ey;
  };
  for (std::size_t q = 0; q < queue_.size(); ++q) {
    const int k = queue_[q];
    const int i = k % w_, j = k / w_;
    const int32_t seed = nearest_[static_cast<std::size_t>(k)];
    const FieldSeed& s = seeds_[static_cast<std::size_t>(seed)];
    for (int dj = -1; dj <= 1; ++dj) {
      const int nj = j + dj;
      if (nj < 0 || nj >= h_) continue;
      for (int di = -1; di <= 1; ++di) {
        const int ni = i + di;
        if ((!di && !dj) || ni < 0 || ni >= w_) continue;
        const double d2 = dist2(ni, nj, s);
        if (d2 > cap2_) continue;
        const std::size_t nk = static_cast<std::size_t>(nj) * w_ + ni;
        const int32_t held = nearest_[nk];
        if (held == seed) continue;
        if (held >= 0 && dist2(ni, nj, seeds_[static_cast<std::size_t>(held)]) <= d2) continue;
        nearest_[nk] = seed;
        queue_.push_back(static_cast<int32_t>(nk));
      }
    }
  }
}

void MatchField::estimateNormals() {
  // Before the brushfire, nearest_ marks exactly the seed cells.
  for (const int32_t k : queue_) {
    const int i = k % w_, j = k / w_;
    double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    int n = 0;
    for (int dj = -kNormalWindow; dj <= kNormalWindow; ++dj) {
      const int nj = j + dj;
      if (nj < 0 || nj >= h_) continue;
      for (int di = -kNormalWindow; di <= kNormalWindow; ++di) {
        const int ni = i + di;
        if (ni < 0 || ni >= w_) continue;
        const int32_t other = nearest_[static_cast<std::size_t>(nj) * w_ + ni];
        if (other < 0) continue;
        const FieldSeed& o = seeds_[static_cast<std::size_t>(other)];
        sx += o.mx;
        sy += o.my;
        sxx += double(o.mx) * o.mx;
        syy += double(o.my) * o.my;
        sxy += double(o.mx) * o.my;
        ++n;
      }
    }
    if (n < kMinNeighbours) continue;
    const double mx = sx / n, my = sy / n;
    const double a = sxx / n - mx * mx, c = syy / n - my * my, b = sxy / n - mx * my;
    const double mid = 0.5 * (a + c), half = std::sqrt(0.25 * (a - c) * (a - c) + b * b);
    const double major = mid + half, minor = mid - half;
    if (major <= 0.0 || minor > kLineRatio * major) continue;
    const double along = 0.5 * std::atan2(2.0 * b, a - c);
    FieldSeed& s = seeds_[static_cast<std::size_t>(nearest_[static_cast<std::size_t>(k)])];
    s.nx = static_cast<float>(-std::sin(along));
    s.ny = static_cast<float>(std::cos(along));
  }
}

}  // namespace gmapping_lite
