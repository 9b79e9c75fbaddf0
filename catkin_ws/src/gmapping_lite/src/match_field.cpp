#include "gmapping_lite/match_field.h"

#include <climits>
#include <cmath>
#include <limits>

namespace gmapping_lite {

namespace {
// A cell is on a wall when its occupied neighbours' means lie along a line: the smaller
// spread is at most this share of the larger.
constexpr double kLineRatio = 0.1;
constexpr int kNormalWindow = 3;  // neighbours within this many cells shape the normal
constexpr int kMinNeighbours = 3;
}  // namespace

void MatchField::build(const GridMap& map, const std::vector<Point>& focus, double reach,
                       double fullness, double radius) {
  const double res = map.resolution();
  inv_res_ = 1.0 / res;
  cap2_ = radius * radius;
  seeds_.clear();
  queue_.clear();
  // Queries land within `reach` of a focus point; the seeds that answer them lie within
  // `radius` further.
  const double reach_cells = (reach + radius) * inv_res_ + 1.0;
  double minx = 0, maxx = 0, miny = 0, maxy = 0;
  for (std::size_t k = 0; k < focus.size(); ++k) {
    const double x = focus[k].x * inv_res_, y = focus[k].y * inv_res_;
    minx = k ? std::min(minx, x) : x;
    maxx = k ? std::max(maxx, x) : x;
    miny = k ? std::min(miny, y) : y;
    maxy = k ? std::max(maxy, y) : y;
  }
  auto blockFloor = [](double cells) {
    return (static_cast<int>(std::floor(cells)) >> kBlockBits) << kBlockBits;
  };
  x0_ = blockFloor(minx - reach_cells);
  y0_ = blockFloor(miny - reach_cells);
  w_ = focus.empty() ? 0 : blockFloor(maxx + reach_cells) + kBlock - x0_;
  h_ = focus.empty() ? 0 : blockFloor(maxy + reach_cells) + kBlock - y0_;
  bw_ = w_ >> kBlockBits;
  bh_ = h_ >> kBlockBits;
  nearest_.assign(static_cast<std::size_t>(w_) * h_, -1);
  state_.assign(static_cast<std::size_t>(w_) * h_, kUnseen);
  markBlocks(focus, reach_cells);
  gatherSeeds(map, fullness);
  estimateNormals(res);
  propagate(res);
}

void MatchField::markBlocks(const std::vector<Point>& focus, double reach_cells) {
  marked_.assign(static_cast<std::size_t>(bw_) * bh_, 0);
  const int span = static_cast<int>(std::ceil(reach_cells / kBlock));
  int last_bx = INT32_MIN, last_by = INT32_MIN;
  for (const Point& p : focus) {
    const int bx = (static_cast<int>(std::floor(p.x * inv_res_)) - x0_) >> kBlockBits;
    const int by = (static_cast<int>(std::floor(p.y * inv_res_)) - y0_) >> kBlockBits;
    if (bx == last_bx && by == last_by) continue;  // neighbouring beams mostly share a block
    last_bx = bx;
    last_by = by;
    for (int j = std::max(0, by - span); j <= std::min(bh_ - 1, by + span); ++j)
      for (int i = std::max(0, bx - span); i <= std::min(bw_ - 1, bx + span); ++i)
        marked_[static_cast<std::size_t>(j) * bw_ + i] = 1;
  }
}

void MatchField::gatherSeeds(const GridMap& map, double fullness) {
  // Seeds: occupied cells of the marked blocks, each holding its own mean hit position. A
  // block lies inside one map patch: one patch lookup per block.
  const double res = map.resolution();
  const int n_patch = GridMap::kPatchSize;
  auto floorDiv = [n_patch](int v) {
    return v >= 0 ? v / n_patch : -((-v + n_patch - 1) / n_patch);
  };
  for (int bj = 0; bj < bh_; ++bj) {
    for (int bi = 0; bi < bw_; ++bi) {
      if (!marked_[static_cast<std::size_t>(bj) * bw_ + bi]) continue;
      const int cx0 = x0_ + bi * kBlock, cy0 = y0_ + bj * kBlock;
      const int px = floorDiv(cx0), py = floorDiv(cy0);
      const Cell* cells = map.patchCells(px, py);
      if (!cells) continue;
      for (int cy = cy0; cy < cy0 + kBlock; ++cy) {
        for (int cx = cx0; cx < cx0 + kBlock; ++cx) {
          const Cell& c = cells[(cy - py * n_patch) * n_patch + (cx - px * n_patch)];
          if (!c.visits) continue;
          const std::size_t k = static_cast<std::size_t>(cy - y0_) * w_ + (cx - x0_);
          if (!c.hits || c.occupancy() <= fullness) {
            state_[k] = kFree;
            continue;
          }
          state_[k] = kOccupied;
          nearest_[k] = static_cast<int32_t>(seeds_.size());
          seeds_.push_back({static_cast<float>((cx + 0.5) * res + c.sum_dx / c.hits),
                            static_cast<float>((cy + 0.5) * res + c.sum_dy / c.hits), 0.0f,
                            0.0f, false});
          queue_.push_back(static_cast<int32_t>(k));
        }
      }
    }
  }
}

void MatchField::propagate(double res) {
  // Brushfire: hand each cell the nearest seed of its neighbours, up to the radius, within the
  // marked blocks. Cells are re-queued when a nearer seed arrives, so the result is the
  // nearest seed in practice. Each cell keeps its best squared distance so far.
  best2_.assign(nearest_.size(), std::numeric_limits<float>::infinity());
  for (const int32_t k : queue_) best2_[static_cast<std::size_t>(k)] = 0.0f;
  const float cell = static_cast<float>(res), cap2 = static_cast<float>(cap2_);
  const float fx0 = static_cast<float>((x0_ + 0.5) * res), fy0 = static_cast<float>((y0_ + 0.5) * res);
  for (std::size_t q = 0; q < queue_.size(); ++q) {
    const int k = queue_[q];
    const int i = k % w_, j = k / w_;
    const int32_t seed = nearest_[static_cast<std::size_t>(k)];
    const FieldSeed& s = seeds_[static_cast<std::size_t>(seed)];
    for (int dj = -1; dj <= 1; ++dj) {
      const int nj = j + dj;
      if (nj < 0 || nj >= h_) continue;
      const float ey = fy0 + nj * cell - s.my;
      for (int di = -1; di <= 1; ++di) {
        const int ni = i + di;
        if ((!di && !dj) || ni < 0 || ni >= w_ || !blockMarked(ni, nj)) continue;
        const float ex = fx0 + ni * cell - s.mx;
        const float d2 = ex * ex + ey * ey;
        const std::size_t nk = static_cast<std::size_t>(nj) * w_ + ni;
        if (d2 > cap2 || d2 >= best2_[nk]) continue;
        best2_[nk] = d2;
        nearest_[nk] = seed;
        queue_.push_back(static_cast<int32_t>(nk));
      }
    }
  }
}

void MatchField::estimateNormals(double res) {
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
    // Which side has the map seen? Cells one and two cells off the wall on either side.
    int free_plus = 0, free_minus = 0;
    for (const double t : {1.5 * res, 2.5 * res}) {
      free_plus += stateAt(s.mx + t * s.nx, s.my + t * s.ny) == kFree;
      free_minus += stateAt(s.mx - t * s.nx, s.my - t * s.ny) == kFree;
    }
    if ((free_plus > 0) != (free_minus > 0)) {
      s.sided = true;
      if (free_minus > 0) {
        s.nx = -s.nx;
        s.ny = -s.ny;
      }
    }
  }
}

}  // namespace gmapping_lite
