#include "gmapping_lite/scan_matcher.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gmapping_lite {

namespace {
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

// Solves the symmetric 3x3 system h x = g by Cramer's rule; false when singular.
bool solve3(const double h[3][3], const double g[3], double x[3]) {
  auto det3 = [](const double m[3][3]) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  const double d = det3(h);
  if (!std::isfinite(d) || std::fabs(d) < 1e-18) return false;
  for (int col = 0; col < 3; ++col) {
    double m[3][3];
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k) m[r][k] = k == col ? g[r] : h[r][k];
    x[col] = det3(m) / d;
  }
  return true;
}
}  // namespace

ScanMatcher::ScanMatcher(const MatcherParams& params) : params_(params) {}

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
  // The field covers the end points as far as a climb may carry them: translation, and the
  // sweep of far points under rotation.
  double reach = 0.0;
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  focus_.clear();
  for (const auto& p : scan.points) {
    focus_.push_back({pose.x + c * p.hx - s * p.hy, pose.y + s * p.hx + c * p.hy});
    reach = std::max(reach, std::hypot(p.hx, p.hy));
  }
  field_.build(map, focus_, 0.3 + 0.05 * reach, params_.fullness, params_.field_radius);
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
  auto odometryLog = [&](const Pose2& p) {
    const double dx = p.x - start.x, dy = p.y - start.y;
    const double dth = normalizeAngle(p.theta - start.theta);
    return -k_xy * (dx * dx + dy * dy) - k_th * dth * dth;
  };
  auto objective = [&](const Pose2& p, double inv) {
    return std::exp(odometryLog(p)) * scoreAt(p, scan, inv);
  };
  Pose2 current = start;
  double ldelta = params_.lstep, adelta = params_.astep;
  const int levels = std::max(1, params_.iterations);
  double inv = 0.0;
  for (int level = 0; level < levels; ++level) {
    // Wide kernels first so a pose some centimetres off still feels the walls.
    const double widen = std::max(1.0, std::ldexp(1.0, params_.kernel_size + 1 - level));
    const double sigma = params_.sigma * widen;
    inv = 0.5 / (sigma * sigma);
    double current_score = objective(current, inv);
    for (int climb = 0; climb < 40; ++climb) {
      const Pose2 moves[6] = {{ldelta, 0, 0}, {-ldelta, 0, 0}, {0, ldelta, 0},
                              {0, -ldelta, 0}, {0, 0, adelta}, {0, 0, -adelta}};
      Pose2 best_local = current;
      double best_local_score = current_score;
      for (const Pose2& m : moves) {
        const Pose2 candidate(current.x + m.x, current.y + m.y,
                              normalizeAngle(current.theta + m.theta));
        const double sc = objective(candidate, inv);
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
  // Keep the ICP polish only if it is better under the same objective.
  const Pose2 refined = refine(current, scan, start, prior);
  const bool take = objective(refined, inv) >= objective(current, inv);
  *best = take ? refined : current;
  return score(*best, scan);
}

Pose2 ScanMatcher::refine(const Pose2& start, const ScanPoints& scan, const Pose2& guess,
                          const OdometryPrior& prior) const {
  Pose2 pose = start;
  // Pairs further apart than this are outliers (unmapped or moved things).
  const double inlier2 = std::pow(2.0 * params_.sigma, 2);
  for (int iteration = 0; iteration < 10; ++iteration) {
    const double c = std::cos(pose.theta), s = std::sin(pose.theta);
    // Normal equations of the residuals linearised in (dx, dy, dtheta), the rotation taken
    // about the robot: one row per wall pairing (along the normal), two for point pairings.
    double h[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, g[3] = {0, 0, 0};
    int pairs = 0;
    auto addRow = [&](double jx, double jy, double jt, double r) {
      const double j[3] = {jx, jy, jt};
      for (int a = 0; a < 3; ++a) {
        g[a] += j[a] * r;
        for (int b = 0; b < 3; ++b) h[a][b] += j[a] * j[b];
      }
    };
    for (const auto& p : scan.points) {
      const double rx = c * p.hx - s * p.hy, ry = s * p.hx + c * p.hy;
      const double x = pose.x + rx, y = pose.y + ry;
      const FieldSeed* seed = field_.seedAt(x, y);
      if (!seed || MatchField::seedDistance2(*seed, x, y) > inlier2) continue;
      ++pairs;
      const double ex = x - seed->mx, ey = y - seed->my;
      if (seed->nx != 0.0f || seed->ny != 0.0f) {
        addRow(seed->nx, seed->ny, -ry * seed->nx + rx * seed->ny, ex * seed->nx + ey * seed->ny);
      } else {
        addRow(1.0, 0.0, -ry, ex);
        addRow(0.0, 1.0, rx, ey);
      }
    }
    if (pairs < 10) break;
    // Residuals count in units of sigma; odometry's guess adds its own information, so a
    // direction the scan does not constrain stays where odometry put it.
    const double w = 1.0 / (params_.sigma * params_.sigma);
    for (int a = 0; a < 3; ++a) {
      g[a] *= w;
      for (int b = 0; b < 3; ++b) h[a][b] *= w;
    }
    const double pxy = prior.sigma_xy > 0 ? 1.0 / (prior.sigma_xy * prior.sigma_xy) : 1e-6;
    const double pth = prior.sigma_theta > 0 ? 1.0 / (prior.sigma_theta * prior.sigma_theta) : 1e-6;
    h[0][0] += pxy;
    h[1][1] += pxy;
    h[2][2] += pth;
    g[0] += pxy * (pose.x - guess.x);
    g[1] += pxy * (pose.y - guess.y);
    g[2] += pth * normalizeAngle(pose.theta - guess.theta);
    double step[3];
    if (!solve3(h, g, step)) break;
    pose = Pose2(pose.x - step[0], pose.y - step[1], normalizeAngle(pose.theta - step[2]));
    if (std::hypot(step[0], step[1]) < 1e-4 && std::fabs(step[2]) < 1e-5) break;
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
