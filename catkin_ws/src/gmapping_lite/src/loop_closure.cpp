#include "gmapping_lite/loop_closure.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

namespace gmapping_lite {

namespace {

// Per-axis position variance and heading variance of an information matrix, through its
// eigen-decomposition: a covariance is never negative. A direction the information leaves
// (numerically) unconstrained, an eigenvalue below double precision's relative resolution of
// the largest (a scan along a corridor, a loop edge of a few collinear points), gets an
// infinite variance on the axes it touches. Inverting by cofactors instead turned such a
// near-singular matrix into a negative variance, whose square root then made every later
// loop search window NaN.
void variances(const Information& info, double* xy, double* theta) {
  Eigen::Matrix3d m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) = 0.5 * (info.m[i][j] + info.m[j][i]);
  *xy = *theta = std::numeric_limits<double>::infinity();
  if (!m.allFinite()) return;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(m);
  if (eigen.info() != Eigen::Success) return;
  const Eigen::Vector3d& lambda = eigen.eigenvalues();  // ascending
  const Eigen::Matrix3d& v = eigen.eigenvectors();
  if (!(lambda(2) > 0.0)) return;
  const double resolvable = lambda(2) * std::numeric_limits<double>::epsilon() * 16.0;
  double c[3] = {0.0, 0.0, 0.0};
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const double share = v(i, j) * v(i, j);
      if (share == 0.0) continue;
      c[i] = lambda(j) > resolvable ? c[i] + share / lambda(j)
                                    : std::numeric_limits<double>::infinity();
    }
  *xy = 0.5 * (c[0] + c[1]);
  *theta = c[2];
}

// Variance a heading variance adds at the end of a lever arm of squared length l2 (none when
// there is no arm: an infinite heading variance times a turn on the spot is no NaN).
double swing(double var_theta, double l2) { return l2 > 0.0 ? var_theta * l2 : 0.0; }

}  // namespace

void relativeUncertainty(const std::vector<const TrajectoryNode*>& chain,
                         const std::vector<PoseEdge>& loops, std::vector<double>* var_xy,
                         std::vector<double>* var_theta) {
  const int n = static_cast<int>(chain.size());
  var_xy->assign(static_cast<std::size_t>(n), 0.0);
  var_theta->assign(static_cast<std::size_t>(n), 0.0);
  if (n == 0) return;
  // Each step adds its own variance, and its heading variance swings the far end by the step's
  // length (the lever arm); a loop edge is a shortcut between the nodes it joins.
  std::vector<double> step_xy(static_cast<std::size_t>(n), 0.0),
      step_theta(static_cast<std::size_t>(n), 0.0);
  for (int k = 1; k < n; ++k)
    variances(chain[static_cast<std::size_t>(k)]->information, &step_xy[k], &step_theta[k]);
  std::vector<std::vector<const PoseEdge*>> from(static_cast<std::size_t>(n));
  for (const PoseEdge& e : loops)
    if (e.from >= 0 && e.to < n && e.from < e.to) from[static_cast<std::size_t>(e.from)].push_back(&e);
  auto length = [&](int a, int b) {
    const Pose2& p = chain[static_cast<std::size_t>(a)]->pose;
    const Pose2& q = chain[static_cast<std::size_t>(b)]->pose;
    return std::hypot(p.x - q.x, p.y - q.y);
  };
  std::vector<double>& vxy = *var_xy;
  std::vector<double>& vth = *var_theta;
  for (int k = n - 2; k >= 0; --k) {
    const double l = length(k, k + 1);
    vxy[k] = vxy[k + 1] + step_xy[k + 1] + swing(vth[k + 1], l * l);
    vth[k] = vth[k + 1] + step_theta[k + 1];
    for (const PoseEdge* e : from[static_cast<std::size_t>(k)]) {
      double exy, eth;
      variances(e->information, &exy, &eth);
      const double l2 = std::pow(length(k, e->to), 2);
      vxy[k] = std::min(vxy[k], vxy[e->to] + exy + swing(vth[e->to], l2));
      vth[k] = std::min(vth[k], vth[e->to] + eth);
    }
  }
  for (int k = 1; k < n; ++k) {
    const double l = length(k - 1, k);
    vxy[k] = std::min(vxy[k], vxy[k - 1] + step_xy[k] + swing(vth[k - 1], l * l));
    vth[k] = std::min(vth[k], vth[k - 1] + step_theta[k]);
  }
}

LoopCloser::LoopCloser(const MatcherParams& matcher, double resolution)
    : matcher_(matcher), resolution_(resolution), max_range_(std::min(matcher.max_range, matcher.max_urange)) {}

bool LoopCloser::find(const std::vector<const TrajectoryNode*>& chain,
                      const std::vector<PoseEdge>& loops, PoseEdge* edge,
                      LoopClosureReport* report) {
  LoopClosureReport local;
  LoopClosureReport& r = report ? *report : local;
  r = LoopClosureReport();
  const int n = static_cast<int>(chain.size());
  if (n < 3) return false;
  const TrajectoryNode& last = *chain.back();
  if (!last.ranges || !last.laser) return false;
  const ScanPoints points = matcher_.matchPoints(*last.laser, *last.ranges);
  if (points.points.size() < 3) return false;
  double far = 0.0, mean_range = 0.0;
  for (const auto& p : points.points) {
    const double d = std::hypot(p.hx, p.hy);
    far = std::max(far, d);
    mean_range += d;
  }
  mean_range /= double(points.points.size());

  std::vector<double> var_xy, var_theta;
  relativeUncertainty(chain, loops, &var_xy, &var_theta);
  // Old nodes worth matching against: near enough to have seen what this scan sees (within
  // the scan's mean range), and placed so loosely relative to it that a match could tell more
  // than the chain does (one standard deviation above half a cell, at the scan's mean range
  // for the heading).
  struct Candidate {
    int index;
    double distance;
  };
  // ... and left behind: since then the robot went further than the laser reaches, there and
  // back, or turned a full circle, so the place has been out of view and this is a return.
  std::vector<double> travelled(static_cast<std::size_t>(n), 0.0), turned(static_cast<std::size_t>(n), 0.0);
  for (int k = n - 2; k >= 0; --k) {
    const Pose2& a = chain[static_cast<std::size_t>(k)]->pose;
    const Pose2& b = chain[static_cast<std::size_t>(k) + 1]->pose;
    travelled[k] = travelled[k + 1] + std::hypot(b.x - a.x, b.y - a.y);
    turned[k] = turned[k + 1] + std::fabs(normalizeAngle(b.theta - a.theta));
  }
  std::vector<Candidate> candidates;
  for (int k = 0; k < n - 1; ++k) {
    const TrajectoryNode& node = *chain[static_cast<std::size_t>(k)];
    if (!node.ranges || !node.laser) continue;
    if (travelled[k] < 2.0 * max_range_ && turned[k] < 2.0 * M_PI) continue;
    const double d = std::hypot(node.pose.x - last.pose.x, node.pose.y - last.pose.y);
    if (d > mean_range) continue;
    const double loose = std::sqrt(var_xy[k]) + std::sqrt(var_theta[k]) * mean_range;
    if (loose < 0.5 * resolution_) continue;
    candidates.push_back({k, d});
  }
  if (candidates.empty()) return false;
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& a, const Candidate& b) { return a.distance < b.distance; });
  // The map of the old scans: as many as one scan's worth of beams per metre of the window's
  // reach would add little; the nearest ones carry what this scan can see.
  const std::size_t keep = std::min<std::size_t>(candidates.size(), 2 * static_cast<std::size_t>(
                                                                          std::ceil(max_range_)));
  candidates.resize(keep);
  const int anchor = candidates.front().index;
  // The window: three standard deviations of the anchor's pose relative to this one, no wider
  // than half the field of view in yaw (beyond that the scans would not overlap) and no wider
  // than the distance the laser sees past the scan's mean range.
  double fov_half = 0.0;
  for (const Beam& b : last.laser->beams) fov_half = std::max(fov_half, std::fabs(b.angle));
  const double window_theta = std::min(3.0 * std::sqrt(var_theta[anchor]), std::max(fov_half, 0.1));
  const double window_xy =
      std::min(3.0 * std::sqrt(var_xy[anchor]), std::max(resolution_, max_range_ - mean_range));
  r.tried = true;
  r.candidates = static_cast<int>(candidates.size());
  r.window_xy = window_xy;
  r.window_theta = window_theta;

  GridMap submap(resolution_);
  for (const Candidate& c : candidates) {
    const TrajectoryNode& node = *chain[static_cast<std::size_t>(c.index)];
    registerScan(&submap, node.pose, *node.laser, *node.ranges, matcher_.params().max_range,
                 matcher_.params().max_urange);
  }
  matcher_.prepare(submap, last.pose, points, window_xy + window_theta * far);
  // A grid of at most 2 x 10 + 1 steps per axis, no finer than two cells (a kernel that wide
  // still feels a wall from between two grid points), then a climb from its best.
  const double step_xy = std::max(2.0 * resolution_, window_xy / 10.0);
  const double step_theta = std::max(step_xy / far, window_theta / 10.0);
  const std::vector<ScanMatcher::Candidate> grid =
      matcher_.search(last.pose, points, window_xy, window_theta, step_xy, step_theta);
  const ScanMatcher::Candidate* top = &grid.front();
  for (const auto& c : grid)
    if (c.value > top->value) top = &c;
  Pose2 refined;
  const OdometryPrior around{step_xy, step_theta};
  matcher_.optimizeFrom(top->pose, top->pose, points, &refined, around);
  matcher_.agreement(refined, points, &r.matched, &r.contradicting);
  // Most of what the old map can check must agree: at least a point per degree of freedom,
  // and twice as many points on mapped walls as in space the old scans saw free.
  if (r.matched < 3 || r.matched < 2 * r.contradicting) return false;
  // No other place in the window may rival the match (see ScanMatcher::margin).
  const Information info = matcher_.information(refined, points, {});
  r.margin = ScanMatcher::margin(grid, *top, info, step_xy, step_theta);
  if (r.margin < std::log(double(grid.size()))) return false;
  const Pose2& old = chain[static_cast<std::size_t>(anchor)]->pose;
  edge->from = anchor;
  edge->to = n - 1;
  edge->measurement = refined.relativeTo(old);
  edge->information = info.rotated(old.theta);
  r.accepted = true;
  return true;
}

}  // namespace gmapping_lite
