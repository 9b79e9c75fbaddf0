#include "gmapping_lite/scan_matcher.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gmapping_lite {

namespace {
constexpr float kNone = std::numeric_limits<float>::quiet_NaN();

// exp(-x) for x >= 0 from a table with linear interpolation (|error| < 2e-5): scoring calls it
// once per beam per candidate pose, and libm's exp was a fifth of the run time.
class NegExpTable {
 public:
  NegExpTable() {
    for (int i = 0; i <= kSize; ++i) table_[i] = std::exp(-double(i) / kScale);
  }
  double operator()(double x) const {
    const double f = x * kScale;
    if (f >= kSize) return 0.0;
    const int i = static_cast<int>(f);
    const double t = f - i;
    return table_[i] + t * (table_[i + 1] - table_[i]);
  }

 private:
  static constexpr int kSize = 4096;
  static constexpr double kScale = 256.0;  // covers x in [0, 16): exp(-16) ~ 1e-7
  double table_[kSize + 1];
};

const NegExpTable negExp;
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
  const std::size_t n = static_cast<std::size_t>(w_) * h_;
  near_x_.assign(n, kNone);
  near_y_.assign(n, kNone);
  queue_.clear();
  // Seeds: occupied cells, each holding its own mean hit position. Walk the map patch by
  // patch (one lookup per patch, not per cell).
  const int n_patch = GridMap::kPatchSize;
  auto floorDiv = [n_patch](int v) { return v >= 0 ? v / n_patch : -((-v + n_patch - 1) / n_patch); };
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
          const int i = cx - x0_, j = cy - y0_;
          const std::size_t k = static_cast<std::size_t>(j) * w_ + i;
          near_x_[k] = static_cast<float>((cx + 0.5) * res + c.sum_dx / c.hits);
          near_y_[k] = static_cast<float>((cy + 0.5) * res + c.sum_dy / c.hits);
          queue_.push_back(static_cast<int>(k));
        }
      }
    }
  }
  // Brushfire: hand each cell the nearest seed of its neighbours, up to `radius`. Cells are
  // re-queued when a nearer seed arrives, so the result is the nearest seed in practice.
  auto dist2 = [&](int i, int j, float sx, float sy) {
    const double ex = (x0_ + i + 0.5) * res - sx, ey = (y0_ + j + 0.5) * res - sy;
    return ex * ex + ey * ey;
  };
  for (std::size_t q = 0; q < queue_.size(); ++q) {
    const int k = queue_[q];
    const int i = k % w_, j = k / w_;
    const float sx = near_x_[k], sy = near_y_[k];
    for (int dj = -1; dj <= 1; ++dj) {
      const int nj = j + dj;
      if (nj < 0 || nj >= h_) continue;
      for (int di = -1; di <= 1; ++di) {
        const int ni = i + di;
        if ((!di && !dj) || ni < 0 || ni >= w_) continue;
        const double d2 = dist2(ni, nj, sx, sy);
        if (d2 > cap2_) continue;
        const std::size_t nk = static_cast<std::size_t>(nj) * w_ + ni;
        if (!std::isnan(near_x_[nk]) && dist2(ni, nj, near_x_[nk], near_y_[nk]) <= d2) continue;
        near_x_[nk] = sx;
        near_y_[nk] = sy;
        queue_.push_back(static_cast<int>(nk));
      }
    }
  }
}

ScanMatcher::ScanMatcher(const MatcherParams& params, double resolution)
    : params_(params), resolution_(resolution) {}

ScanPoints ScanMatcher::matchPoints(const LaserGeometry& laser, const Ranges& ranges) const {
  ScanPoints out;
  const std::size_t n = std::min(laser.beams.size(), ranges.size());
  const std::size_t step = static_cast<std::size_t>(std::max(0, params_.lskip)) + 1;
  out.points.reserve(n / step + 1);
  for (std::size_t i = 0; i < n; i += step) {
    const double r = ranges[i];
    if (!std::isfinite(r) || r <= 0.0 || r > params_.max_urange || r > params_.max_range)
      continue;
    const Beam& b = laser.beams[i];
    const double d = r * b.scale;
    out.points.push_back({laser.origin.x + d * std::cos(b.angle),
                          laser.origin.y + d * std::sin(b.angle)});
  }
  return out;
}

void ScanMatcher::prepare(const GridMap& map, const Pose2& pose, const ScanPoints& scan) {
  // Field: bounding box of the end points, widened for the distance a climb may travel
  // (translation, and the sweep of far points under rotation).
  double minx = pose.x, maxx = pose.x, miny = pose.y, maxy = pose.y, reach = 0.0;
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  for (const auto& p : scan.points) {
    const double wx = pose.x + c * p.hx - s * p.hy, wy = pose.y + s * p.hx + c * p.hy;
    minx = std::min(minx, wx);
    maxx = std::max(maxx, wx);
    miny = std::min(miny, wy);
    maxy = std::max(maxy, wy);
    reach = std::max(reach, std::hypot(p.hx, p.hy));
  }
  const double margin = 0.3 + 0.05 * reach + params_.field_radius;
  const GridMap grid(resolution_);
  const CellIndex lo = grid.toCell(minx - margin, miny - margin);
  const CellIndex hi = grid.toCell(maxx + margin, maxy + margin);
  field_.build(map, lo, {hi.x + 1, hi.y + 1}, params_.fullness, params_.field_radius);
}

double ScanMatcher::scoreAt(const Pose2& pose, const ScanPoints& scan,
                            double inv_two_sigma2) const {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  double total = 0.0;
  for (const auto& p : scan.points) {
    const double d2 =
        field_.distance2(pose.x + c * p.hx - s * p.hy, pose.y + s * p.hx + c * p.hy);
    total += negExp(d2 * inv_two_sigma2);
  }
  return total;
}

double ScanMatcher::score(const Pose2& pose, const ScanPoints& scan) const {
  return scoreAt(pose, scan, 0.5 / (params_.sigma * params_.sigma));
}

double ScanMatcher::likelihood(const Pose2& pose, const ScanPoints& scan, double* score) const {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  const double inv_sigma = 0.5 / (params_.sigma * params_.sigma);
  const double inv_lsigma = 0.5 / (params_.lsigma * params_.lsigma);
  // A beam that matches nothing counts as one 3 lsigma off (gmapping's "null likelihood").
  const double cap2 = 9.0 * params_.lsigma * params_.lsigma;
  double l = 0.0, sc = 0.0;
  for (const auto& p : scan.points) {
    const double d2 =
        field_.distance2(pose.x + c * p.hx - s * p.hy, pose.y + s * p.hx + c * p.hy);
    sc += std::exp(-d2 * inv_sigma);
    l -= std::min(d2, cap2) * inv_lsigma;
  }
  if (score) *score = sc;
  return l;
}

double ScanMatcher::optimize(const Pose2& start, const ScanPoints& scan, Pose2* best,
                             const OdometryPrior& prior) const {
  const double k_xy = prior.sigma_xy > 0 ? 0.5 / (prior.sigma_xy * prior.sigma_xy) : 0.0;
  const double k_th = prior.sigma_theta > 0 ? 0.5 / (prior.sigma_theta * prior.sigma_theta) : 0.0;
  auto odometryGain = [&](const Pose2& p) {
    const double dx = p.x - start.x, dy = p.y - start.y;
    const double dth = normalizeAngle(p.theta - start.theta);
    return std::exp(-k_xy * (dx * dx + dy * dy) - k_th * dth * dth);
  };
  Pose2 current = start;
  double ldelta = params_.lstep, adelta = params_.astep;
  const int levels = std::max(1, params_.iterations);
  for (int level = 0; level < levels; ++level) {
    // Wide kernels first so a pose some centimetres off still feels the walls.
    const double widen = std::max(1.0, std::ldexp(1.0, params_.kernel_size + 1 - level));
    const double sigma = params_.sigma * widen;
    const double inv = 0.5 / (sigma * sigma);
    double current_score = odometryGain(current) * scoreAt(current, scan, inv);
    for (int climb = 0; climb < 40; ++climb) {
      const Pose2 moves[6] = {{ldelta, 0, 0}, {-ldelta, 0, 0}, {0, ldelta, 0},
                              {0, -ldelta, 0}, {0, 0, adelta}, {0, 0, -adelta}};
      Pose2 best_local = current;
      double best_local_score = current_score;
      for (const Pose2& m : moves) {
        const Pose2 candidate(current.x + m.x, current.y + m.y,
                              normalizeAngle(current.theta + m.theta));
        const double sc = odometryGain(candidate) * scoreAt(candidate, scan, inv);
        if (sc > best_local_score) {
          best_local_score = sc;
          best_local = candidate;
        }
      }
      if (best_local_score <= current_score) break;
      current = best_local;
      current_score = best_local_score;
    }
    ldelta *= 0.5;
    adelta *= 0.5;
  }
  // Keep the ICP polish only if it is better under the same odometry prior.
  const Pose2 refined = refine(current, scan);
  const double climbed = score(current, scan), polished = score(refined, scan);
  const bool take = polished * odometryGain(refined) >= climbed * odometryGain(current);
  *best = take ? refined : current;
  return take ? polished : climbed;
}

Pose2 ScanMatcher::refine(const Pose2& start, const ScanPoints& scan) const {
  Pose2 pose = start;
  // Pairs further apart than this are outliers (unmapped or moved things).
  const double inlier2 = std::pow(2.0 * params_.sigma, 2);
  for (int iteration = 0; iteration < 10; ++iteration) {
    const double c = std::cos(pose.theta), s = std::sin(pose.theta);
    double n = 0, ax = 0, ay = 0, qx = 0, qy = 0;
    std::vector<double> pairs;
    pairs.reserve(scan.points.size() * 4);
    for (const auto& p : scan.points) {
      const double x = pose.x + c * p.hx - s * p.hy, y = pose.y + s * p.hx + c * p.hy;
      double mx = 0.0, my = 0.0;
      if (field_.nearest(x, y, &mx, &my) > inlier2) continue;
      pairs.insert(pairs.end(), {x, y, mx, my});
      ax += x;
      ay += y;
      qx += mx;
      qy += my;
      n += 1;
    }
    if (n < 10) break;
    ax /= n, ay /= n, qx /= n, qy /= n;
    double sxx = 0, sxy = 0;  // cross terms of the centred pairs
    for (std::size_t k = 0; k < pairs.size(); k += 4) {
      const double px = pairs[k] - ax, py = pairs[k + 1] - ay;
      const double mx = pairs[k + 2] - qx, my = pairs[k + 3] - qy;
      sxx += px * mx + py * my;
      sxy += px * my - py * mx;
    }
    const double dth = std::atan2(sxy, sxx);
    const double cr = std::cos(dth), sr = std::sin(dth);
    // Rotate the pose about the scan's centroid, then move that centroid onto the means'.
    const double tx = qx - (cr * ax - sr * ay), ty = qy - (sr * ax + cr * ay);
    const Pose2 next(cr * pose.x - sr * pose.y + tx, sr * pose.x + cr * pose.y + ty,
                     normalizeAngle(pose.theta + dth));
    const bool settled = std::hypot(next.x - pose.x, next.y - pose.y) < 1e-4 && std::fabs(dth) < 1e-5;
    pose = next;
    if (settled) break;
  }
  return pose;
}

double ScanMatcher::match(const GridMap& map, const Pose2& start, const ScanPoints& scan,
                          Pose2* best, const OdometryPrior& prior) {
  prepare(map, start, scan);
  return optimize(start, scan, best, prior);
}

void registerScan(GridMap* map, const Pose2& pose, const LaserGeometry& laser,
                  const Ranges& ranges, double max_range, double max_urange) {
  const Pose2 origin = pose * Pose2(laser.origin.x, laser.origin.y, 0.0);
  const std::size_t n = std::min(laser.beams.size(), ranges.size());
  for (std::size_t i = 0; i < n; ++i) {
    const double r = ranges[i];
    if (std::isnan(r) || r <= 0.0) continue;
    bool hit = true;
    double d = r;
    if (std::isinf(r)) {
      hit = false;  // no return: the whole usable range is free
      d = max_urange;
    } else if (r > max_range) {
      continue;
    } else if (r > max_urange) {
      hit = false;
      d = max_urange;
    }
    const Beam& b = laser.beams[i];
    const double a = pose.theta + b.angle, h = d * b.scale;
    map->traceBeam(origin.x, origin.y, origin.x + h * std::cos(a), origin.y + h * std::sin(a), hit);
  }
}

}  // namespace gmapping_lite
