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

// gmapping's null likelihood: a beam that matches nothing counts as one 3 sigma off.
constexpr double kNullLog = -4.5;

// log(eps + (1 - eps) exp(-x)) for x >= 0, eps = exp(kNullLog): a Gaussian beam model mixed
// with the null likelihood, so a far point costs no more than a missing one. From a table.
class LogMixTable {
 public:
  explicit LogMixTable(double null_log = kNullLog) {
    const double eps = std::exp(null_log);
    for (int i = 0; i <= kSize; ++i)
      table_[i] = std::log(eps + (1.0 - eps) * std::exp(-double(i) / kScale));
  }
  double operator()(double x) const {
    const double f = x * kScale;
    if (f >= kSize) return table_[kSize];
    const int i = static_cast<int>(f);
    const double t = f - i;
    return table_[i] + t * (table_[i + 1] - table_[i]);
  }

 private:
  static constexpr int kSize = 4096;
  static constexpr double kScale = 128.0;  // covers x in [0, 32): the mixture is flat beyond
  double table_[kSize + 1];
};

const LogMixTable logMix;

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

// Eigen-decomposition of a symmetric 3x3 matrix by Jacobi rotations: values[k] belongs to the
// column vectors[.][k].
void eigenSymmetric3(const double a_in[3][3], double values[3], double vectors[3][3]) {
  double a[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      a[i][j] = a_in[i][j];
      vectors[i][j] = i == j ? 1.0 : 0.0;
    }
  for (int sweep = 0; sweep < 50; ++sweep) {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    if (off < 1e-30) break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (std::fabs(a[p][q]) < 1e-300) continue;
        const double theta = 0.5 * (a[q][q] - a[p][p]) / a[p][q];
        const double t = (theta >= 0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        for (int k = 0; k < 3; ++k) {  // a <- a J
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 3; ++k) {  // a <- J^T a
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        for (int k = 0; k < 3; ++k) {
          const double vkp = vectors[k][p], vkq = vectors[k][q];
          vectors[k][p] = c * vkp - s * vkq;
          vectors[k][q] = s * vkp + c * vkq;
        }
      }
  }
  for (int i = 0; i < 3; ++i) values[i] = a[i][i];
}
}  // namespace

ScanMatcher::ScanMatcher(const MatcherParams& params) : params_(params) {}

ScanPoints ScanMatcher::matchPoints(const LaserGeometry& laser, const Ranges& ranges) const {
  ScanPoints out;
  const std::size_t n = std::min(laser.beams.size(), ranges.size());
  const std::size_t step = static_cast<std::size_t>(std::max(0, params_.lskip)) + 1;
  out.points.reserve(n / step + 1);
  const double merge2 = params_.merge_distance * params_.merge_distance;
  // The group of consecutive beams being merged: the first end point, and sums.
  double fx = 0, fy = 0, sx = 0, sy = 0, sux = 0, suy = 0;
  int count = 0;
  auto flush = [&]() {
    if (!count) return;
    const double norm = std::hypot(sux, suy);
    out.points.push_back({sx / count, sy / count, sux / norm, suy / norm, double(count)});
    out.beams += count;
    count = 0;
  };
  for (std::size_t i = 0; i < n; i += step) {
    const double r = ranges[i];
    if (!std::isfinite(r) || r <= 0.0 || r > params_.max_urange || r > params_.max_range) {
      flush();
      continue;
    }
    const Beam& b = laser.beams[i];
    const double d = r * b.scale, ux = std::cos(b.angle), uy = std::sin(b.angle);
    const double hx = laser.origin.x + d * ux, hy = laser.origin.y + d * uy;
    if (count && (hx - fx) * (hx - fx) + (hy - fy) * (hy - fy) > merge2) flush();
    if (!count) {
      fx = hx;
      fy = hy;
      sx = sy = sux = suy = 0.0;
    }
    sx += hx;
    sy += hy;
    sux += ux;
    suy += uy;
    ++count;
  }
  flush();
  return out;
}

void ScanMatcher::prepare(const GridMap& map, const Pose2& pose, const ScanPoints& scan,
                          double search) {
  // The field covers the end points as far as a climb may carry them: translation, and the
  // sweep of far points under rotation.
  double reach = 0.0;
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  focus_.clear();
  for (const auto& p : scan.points) {
    focus_.push_back({pose.x + c * p.hx - s * p.hy, pose.y + s * p.hx + c * p.hy});
    reach = std::max(reach, std::hypot(p.hx, p.hy));
  }
  field_.build(map, focus_, 0.3 + 0.05 * reach + search, params_.fullness,
               params_.field_radius);
}

double ScanMatcher::pointLogLikelihood(const Pose2& pose, const ScanPoints& scan,
                                       double inv) const {
  // A contradiction scores as a match at the field's radius (the worst a match can score at
  // this kernel); an unseen end point half as badly (no evidence either way, in log terms).
  const double contradict = logMix(field_.cap2() * inv), unknown = 0.5 * contradict;
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  double total = 0.0;
  for (const auto& p : scan.points) {
    const EndPoint e = field_.query(pose.x + c * p.hx - s * p.hy, pose.y + s * p.hx + c * p.hy,
                                    c * p.ux - s * p.uy, s * p.ux + c * p.uy);
    const double w = p.beams;
    switch (e.state) {
      case EndState::kMatched:
        total += w * logMix(e.d2 * inv);
        break;
      case EndState::kContradict:
        total += w * contradict;
        break;
      case EndState::kUnknown:
        total += w * unknown;
        break;
    }
  }
  return total;
}

double ScanMatcher::score(const Pose2& pose, const ScanPoints& scan) const {
  double sc = 0.0;
  likelihood(pose, scan, &sc);
  return sc;
}

double ScanMatcher::likelihood(const Pose2& pose, const ScanPoints& scan, double* score) const {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  const double inv_sigma = 0.5 / (params_.sigma * params_.sigma);
  const double inv_lsigma = 0.5 / (params_.lsigma * params_.lsigma);
  double l = 0.0, sc = 0.0;
  for (const auto& p : scan.points) {
    const EndPoint e = field_.query(pose.x + c * p.hx - s * p.hy, pose.y + s * p.hx + c * p.hy,
                                    c * p.ux - s * p.uy, s * p.ux + c * p.uy);
    switch (e.state) {
      case EndState::kMatched:
        sc += p.beams * negExp(e.d2 * inv_sigma);
        l += p.beams * logMix(e.d2 * inv_lsigma);
        break;
      case EndState::kContradict:
        l += p.beams * kNullLog;
        break;
      case EndState::kUnknown:
        l += p.beams * 0.5 * kNullLog;
        break;
    }
  }
  if (score) *score = sc;
  return l;
}

namespace {
double priorLog(const Pose2& p, const Pose2& centre, const OdometryPrior& prior) {
  double l = 0.0;
  if (prior.sigma_xy > 0) {
    const double dx = p.x - centre.x, dy = p.y - centre.y;
    l -= (dx * dx + dy * dy) / (2.0 * prior.sigma_xy * prior.sigma_xy);
  }
  if (prior.sigma_theta > 0) {
    const double dth = normalizeAngle(p.theta - centre.theta);
    l -= dth * dth / (2.0 * prior.sigma_theta * prior.sigma_theta);
  }
  return l;
}
}  // namespace

double ScanMatcher::objective(const Pose2& pose, const Pose2& centre, const ScanPoints& scan,
                              const OdometryPrior& prior) const {
  return pointLogLikelihood(pose, scan, 0.5 / (params_.sigma * params_.sigma)) +
         priorLog(pose, centre, prior);
}

ScanPoints ScanMatcher::knownPoints(const Pose2& pose, const ScanPoints& all, double reach) const {
  // The pose itself, then moved by +-reach along x and along y.
  const Pose2 poses[5] = {pose,
                          {pose.x + reach, pose.y, pose.theta},
                          {pose.x - reach, pose.y, pose.theta},
                          {pose.x, pose.y + reach, pose.theta},
                          {pose.x, pose.y - reach, pose.theta}};
  const int count = reach > 0.0 ? 5 : 1;
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  ScanPoints out;
  out.points.reserve(all.points.size());
  for (const auto& p : all.points) {
    bool known = true;
    for (int k = 0; k < count && known; ++k) {
      const EndPoint e =
          field_.query(poses[k].x + c * p.hx - s * p.hy, poses[k].y + s * p.hx + c * p.hy,
                       c * p.ux - s * p.uy, s * p.ux + c * p.uy);
      known = e.state != EndState::kUnknown;
    }
    if (!known) continue;
    out.points.push_back(p);
    out.beams += p.beams;
  }
  return out;
}

double ScanMatcher::optimize(const Pose2& start, const ScanPoints& scan, Pose2* best,
                             const OdometryPrior& prior) const {
  return optimizeFrom(start, start, scan, best, prior);
}

double ScanMatcher::optimizeFrom(const Pose2& start, const Pose2& centre,
                                 const ScanPoints& all, Pose2* best,
                                 const OdometryPrior& prior) const {
  // Match with the points that land where the map has seen something: an end point in space
  // never seen (a wall beyond the mapped end of the one in view, a new room) says nothing of
  // the pose, and would only pull the scan towards the mapped part. "Seen" wherever the climb
  // may carry the point (knownPoints): the climb is held within about the prior's sd of its
  // centre, and starts offset from it by the start's distance from the centre, so its reach
  // is that offset plus the prior's translation sd. Translation only: a reach in heading
  // sweeps an end point by the reach times its range (with gmapping's default motion noise
  // about 0.2 rad an update: a metre at 5 m), which leaves little of the scan (twelfth
  // attempt, a2 against a6, bench/slam_robustness_notes.md).
  const double reach = std::hypot(start.x - centre.x, start.y - centre.y) +
                       std::max(0.0, prior.sigma_xy);
  const ScanPoints scan = knownPoints(start, all, reach);
  Pose2 current = start;
  double ldelta = params_.lstep, adelta = params_.astep;
  const int levels = std::max(1, params_.iterations);
  for (int level = 0; level < levels; ++level) {
    // Wide kernels first so a pose some centimetres off still feels the walls.
    const double widen = std::max(1.0, std::ldexp(1.0, params_.kernel_size + 1 - level));
    const double sigma = params_.sigma * widen;
    const double inv = 0.5 / (sigma * sigma);
    auto value = [&](const Pose2& p) {
      return pointLogLikelihood(p, scan, inv) + priorLog(p, centre, prior);
    };
    double current_value = value(current);
    for (int climb = 0; climb < 40; ++climb) {
      const Pose2 moves[6] = {{ldelta, 0, 0}, {-ldelta, 0, 0}, {0, ldelta, 0},
                              {0, -ldelta, 0}, {0, 0, adelta}, {0, 0, -adelta}};
      Pose2 best_local = current;
      double best_local_value = current_value;
      for (const Pose2& m : moves) {
        const Pose2 candidate(current.x + m.x, current.y + m.y,
                              normalizeAngle(current.theta + m.theta));
        const double v = value(candidate);
        if (v > best_local_value) {
          best_local_value = v;
          best_local = candidate;
        }
      }
      if (best_local_value <= current_value) break;
      current = best_local;
      current_value = best_local_value;
    }
    ldelta *= 0.5;
    adelta *= 0.5;
  }
  // Keep the Gauss-Newton polish only if it is better under the fine objective.
  const Pose2 refined = refine(current, scan, centre, prior);
  const bool take =
      objective(refined, centre, scan, prior) >= objective(current, centre, scan, prior);
  *best = take ? refined : current;
  *best = keepUnconstrained(*best, centre, scan, prior);
  return score(*best, all);
}

int ScanMatcher::normalEquations(const Pose2& pose, const ScanPoints& scan, double h[3][3],
                                 double g[3], bool per_beam) const {
  // Pairs further apart than this are outliers (unmapped or moved things).
  const double inlier2 = std::pow(2.0 * params_.sigma, 2);
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  // Residuals linearised in (dx, dy, dtheta), the rotation taken about the robot: one row per
  // wall pairing (along the normal), two for point pairings.
  for (int a = 0; a < 3; ++a) {
    g[a] = 0.0;
    for (int b = 0; b < 3; ++b) h[a][b] = 0.0;
  }
  int pairs = 0;
  double w = 1.0;
  auto addRow = [&](double jx, double jy, double jt, double r) {
    const double j[3] = {jx, jy, jt};
    for (int a = 0; a < 3; ++a) {
      g[a] += w * j[a] * r;
      for (int b = 0; b < 3; ++b) h[a][b] += w * j[a] * j[b];
    }
  };
  for (const auto& p : scan.points) {
    const double rx = c * p.hx - s * p.hy, ry = s * p.hx + c * p.hy;
    const double x = pose.x + rx, y = pose.y + ry;
    const EndPoint e = field_.query(x, y, c * p.ux - s * p.uy, s * p.ux + c * p.uy);
    if (e.state != EndState::kMatched || e.d2 > inlier2) continue;
    ++pairs;
    w = per_beam ? p.beams : 1.0;
    const FieldSeed* seed = e.seed;
    const double ex = x - seed->mx, ey = y - seed->my;
    if (e.across) {
      addRow(seed->nx, seed->ny, -ry * seed->nx + rx * seed->ny, ex * seed->nx + ey * seed->ny);
    } else {
      addRow(1.0, 0.0, -ry, ex);
      addRow(0.0, 1.0, rx, ey);
    }
  }
  return pairs;
}

Pose2 ScanMatcher::refine(const Pose2& start, const ScanPoints& scan, const Pose2& centre,
                          const OdometryPrior& prior) const {
  Pose2 pose = start;
  for (int iteration = 0; iteration < 10; ++iteration) {
    double h[3][3], g[3];
    if (normalEquations(pose, scan, h, g) < 10) break;
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
    g[0] += pxy * (pose.x - centre.x);
    g[1] += pxy * (pose.y - centre.y);
    g[2] += pth * normalizeAngle(pose.theta - centre.theta);
    double step[3];
    if (!solve3(h, g, step)) break;
    pose = Pose2(pose.x - step[0], pose.y - step[1], normalizeAngle(pose.theta - step[2]));
    if (std::hypot(step[0], step[1]) < 1e-4 && std::fabs(step[2]) < 1e-5) break;
  }
  return pose;
}

Pose2 ScanMatcher::keepUnconstrained(const Pose2& pose, const Pose2& centre,
                                     const ScanPoints& scan, const OdometryPrior& prior) const {
  if (prior.sigma_xy <= 0.0 || prior.sigma_theta <= 0.0 ) return pose;
  // The scan's information at the match (points in units of sigma), per principal direction,
  // against the odometry prior's along the same direction: where odometry knows more than the
  // scan (along a corridor, a lone wall), the match keeps odometry's value, so faint gradients
  // in that direction (a slightly bent wall end, a far jamb) cannot carry the pose off.
  double h[3][3], g[3];
  if (normalEquations(pose, scan, h, g) < 3) return pose;
  const double w = 1.0 / (params_.sigma * params_.sigma);
  for (auto& row : h)
    for (double& v : row) v *= w;
  double values[3], vectors[3][3];
  eigenSymmetric3(h, values, vectors);
  const double pxy = 1.0 / (prior.sigma_xy * prior.sigma_xy);
  const double pth = 1.0 / (prior.sigma_theta * prior.sigma_theta);
  double delta[3] = {pose.x - centre.x, pose.y - centre.y, normalizeAngle(pose.theta - centre.theta)};
  for (int k = 0; k < 3; ++k) {
    const double v[3] = {vectors[0][k], vectors[1][k], vectors[2][k]};
    const double prior_info = pxy * (v[0] * v[0] + v[1] * v[1]) + pth * v[2] * v[2];
    if (values[k] >= prior_info) continue;
    const double along = v[0] * delta[0] + v[1] * delta[1] + v[2] * delta[2];
    for (int i = 0; i < 3; ++i) delta[i] -= along * v[i];
  }
  return Pose2(centre.x + delta[0], centre.y + delta[1], normalizeAngle(centre.theta + delta[2]));
}

Information ScanMatcher::information(const Pose2& pose, const ScanPoints& scan,
                                     const OdometryPrior& prior) const {
  Information info;
  double g[3];
  if (normalEquations(pose, scan, info.m, g) >= 3) {
    const double w = 1.0 / (params_.sigma * params_.sigma);
    for (auto& row : info.m)
      for (double& v : row) v *= w;
  } else {
    info = Information();
  }
  if (prior.sigma_xy > 0) {
    info.m[0][0] += 1.0 / (prior.sigma_xy * prior.sigma_xy);
    info.m[1][1] += 1.0 / (prior.sigma_xy * prior.sigma_xy);
  }
  if (prior.sigma_theta > 0) info.m[2][2] += 1.0 / (prior.sigma_theta * prior.sigma_theta);
  return info;
}

Information ScanMatcher::calibratedInformation(const Pose2& pose, const ScanPoints& scan) const {
  Information info;
  double g[3];
  if (normalEquations(pose, scan, info.m, g, false) < 3) return Information();
  const double w = 1.0 / (params_.lsigma * params_.lsigma);
  for (auto& row : info.m)
    for (double& v : row) v *= w;
  return info;
}

void ScanMatcher::agreement(const Pose2& pose, const ScanPoints& scan, int* matched,
                            int* contradicting) const {
  const double inlier2 = std::pow(2.0 * params_.sigma, 2);
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  *matched = *contradicting = 0;
  for (const auto& p : scan.points) {
    const EndPoint e = field_.query(pose.x + c * p.hx - s * p.hy, pose.y + s * p.hx + c * p.hy,
                                    c * p.ux - s * p.uy, s * p.ux + c * p.uy);
    if (e.state == EndState::kMatched && e.d2 <= inlier2) {
      ++*matched;
    } else if (e.state != EndState::kUnknown) {
      ++*contradicting;
    }
  }
}

std::vector<ScanMatcher::Candidate> ScanMatcher::search(const Pose2& centre,
                                                        const ScanPoints& scan, double window_xy,
                                                        double window_theta, double step_xy,
                                                        double step_theta) const {
  const int nt = static_cast<int>(std::ceil(window_theta / step_theta));
  const int nxy = static_cast<int>(std::ceil(window_xy / step_xy));
  const double inv = 0.5 / (step_xy * step_xy);
  const double contradict = logMix(field_.cap2() * inv), unknown = 0.5 * contradict;
  std::vector<Candidate> out;
  out.reserve(static_cast<std::size_t>(2 * nt + 1) * (2 * nxy + 1) * (2 * nxy + 1));
  const std::size_t n = scan.points.size();
  std::vector<double> wx(n), wy(n), ux(n), uy(n);
  for (int it = -nt; it <= nt; ++it) {
    const double theta = normalizeAngle(centre.theta + it * step_theta);
    const double c = std::cos(theta), s = std::sin(theta);
    for (std::size_t k = 0; k < n; ++k) {
      const auto& p = scan.points[k];
      wx[k] = centre.x + c * p.hx - s * p.hy;
      wy[k] = centre.y + s * p.hx + c * p.hy;
      ux[k] = c * p.ux - s * p.uy;
      uy[k] = s * p.ux + c * p.uy;
    }
    for (int ix = -nxy; ix <= nxy; ++ix)
      for (int iy = -nxy; iy <= nxy; ++iy) {
        const double dx = ix * step_xy, dy = iy * step_xy;
        double total = 0.0;
        for (std::size_t k = 0; k < n; ++k) {
          const EndPoint e = field_.query(wx[k] + dx, wy[k] + dy, ux[k], uy[k]);
          total += e.state == EndState::kMatched
                       ? logMix(e.d2 * inv)
                       : (e.state == EndState::kUnknown ? unknown : contradict);
        }
        out.push_back({Pose2(centre.x + dx, centre.y + dy, theta), total});
      }
  }
  return out;
}

double ScanMatcher::margin(const std::vector<Candidate>& grid, const Candidate& top,
                           const Information& info, double step_xy, double step_theta) {
  double runner_up = -std::numeric_limits<double>::infinity();
  for (const auto& c : grid) {
    const double d[3] = {c.pose.x - top.pose.x, c.pose.y - top.pose.y,
                         normalizeAngle(c.pose.theta - top.pose.theta)};
    // The grid's own spacing blurs the peak: distances are counted beyond one step.
    const double shrink[3] = {std::max(0.0, std::fabs(d[0]) - step_xy) * (d[0] < 0 ? -1 : 1),
                              std::max(0.0, std::fabs(d[1]) - step_xy) * (d[1] < 0 ? -1 : 1),
                              std::max(0.0, std::fabs(d[2]) - step_theta) * (d[2] < 0 ? -1 : 1)};
    double m2 = 0.0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m2 += shrink[i] * info.m[i][j] * shrink[j];
    if (m2 <= 9.0) continue;
    runner_up = std::max(runner_up, c.value);
  }
  return top.value - runner_up;
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
      // No return: free as far as the laser reaches and the usable range allows (maxUrange
      // may be set beyond maxRange, gmapping's default of 80 m for an 8 m sensor).
      hit = false;
      d = std::min(max_urange, max_range);
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
