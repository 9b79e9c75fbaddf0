#include "synthetic.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace gmapping_lite {

SyntheticWorld::SyntheticWorld(double width, double height, double resolution)
    : width_(width),
      height_(height),
      res_(resolution),
      nx_(static_cast<int>(std::ceil(width / resolution))),
      ny_(static_cast<int>(std::ceil(height / resolution))),
      cells_(static_cast<std::size_t>(nx_) * ny_, 0) {}

void SyntheticWorld::fillRect(double x0, double y0, double x1, double y1, bool occ) {
  const int i0 = std::max(0, static_cast<int>(std::floor(x0 / res_)));
  const int j0 = std::max(0, static_cast<int>(std::floor(y0 / res_)));
  const int i1 = std::min(nx_, static_cast<int>(std::ceil(x1 / res_)));
  const int j1 = std::min(ny_, static_cast<int>(std::ceil(y1 / res_)));
  for (int j = j0; j < j1; ++j)
    for (int i = i0; i < i1; ++i) cells_[static_cast<std::size_t>(j) * nx_ + i] = occ ? 1 : 0;
}

bool SyntheticWorld::cellOccupied(int i, int j) const {
  if (i < 0 || j < 0 || i >= nx_ || j >= ny_) return false;
  return cells_[static_cast<std::size_t>(j) * nx_ + i] != 0;
}

bool SyntheticWorld::occupied(double x, double y) const {
  return cellOccupied(static_cast<int>(std::floor(x / res_)), static_cast<int>(std::floor(y / res_)));
}

double SyntheticWorld::castRay(double x, double y, double angle, double max_range) const {
  // Amanatides-Woo grid traversal; returns the distance at which the ray enters a wall cell.
  const double dx = std::cos(angle), dy = std::sin(angle);
  int i = static_cast<int>(std::floor(x / res_)), j = static_cast<int>(std::floor(y / res_));
  const int si = dx > 0 ? 1 : -1, sj = dy > 0 ? 1 : -1;
  const double inf = std::numeric_limits<double>::infinity();
  const double tdx = dx != 0 ? res_ / std::fabs(dx) : inf, tdy = dy != 0 ? res_ / std::fabs(dy) : inf;
  double tx = dx != 0 ? ((i + (si > 0 ? 1 : 0)) * res_ - x) / dx : inf;
  double ty = dy != 0 ? ((j + (sj > 0 ? 1 : 0)) * res_ - y) / dy : inf;
  double t = 0.0;
  while (t <= max_range) {
    if (cellOccupied(i, j)) return t;
    if (tx < ty) {
      t = tx;
      tx += tdx;
      i += si;
    } else {
      t = ty;
      ty += tdy;
      j += sj;
    }
    if (i < -1 || j < -1 || i > nx_ || j > ny_) break;
  }
  return inf;
}

double SyntheticWorld::distanceToWall(double x, double y, double radius) const {
  const int r = static_cast<int>(std::ceil(radius / res_));
  const int ci = static_cast<int>(std::floor(x / res_)), cj = static_cast<int>(std::floor(y / res_));
  double best = std::numeric_limits<double>::infinity();
  for (int j = cj - r; j <= cj + r; ++j)
    for (int i = ci - r; i <= ci + r; ++i) {
      if (!cellOccupied(i, j)) continue;
      // Distance to the cell's square, not its centre: walls are the cells' edges.
      const double ex = std::max({0.0, i * res_ - x, x - (i + 1) * res_});
      const double ey = std::max({0.0, j * res_ - y, y - (j + 1) * res_});
      best = std::min(best, std::hypot(ex, ey));
    }
  return best;
}

SyntheticWorld SyntheticWorld::office() {
  SyntheticWorld w(16.0, 10.0, 0.025);
  const double t = 0.1;  // wall thickness
  w.fillRect(0, 0, 16, t);
  w.fillRect(0, 10 - t, 16, 10);
  w.fillRect(0, 0, t, 10);
  w.fillRect(16 - t, 0, 16, 10);
  // A corridor along y = 4.5..5.5 with rooms above and below; doorways 1 m wide.
  w.fillRect(0, 4.0, 2.5, 4.0 + t);
  w.fillRect(3.5, 4.0, 7.5, 4.0 + t);
  w.fillRect(8.5, 4.0, 12.5, 4.0 + t);
  w.fillRect(13.5, 4.0, 16, 4.0 + t);
  w.fillRect(0, 6.0, 4.5, 6.0 + t);
  w.fillRect(5.5, 6.0, 10.5, 6.0 + t);
  w.fillRect(11.5, 6.0, 16, 6.0 + t);
  w.fillRect(5.0, 0, 5.0 + t, 4.0);
  w.fillRect(10.0, 0, 10.0 + t, 4.0);
  w.fillRect(8.0, 6.0, 8.0 + t, 10.0);
  // Furniture: boxes and a pillar give the matcher corners to lock on to.
  w.fillRect(1.0, 1.0, 1.8, 1.6);
  w.fillRect(3.5, 2.5, 4.2, 3.0);
  w.fillRect(7.0, 1.2, 7.6, 2.0);
  w.fillRect(12.0, 1.0, 13.0, 1.5);
  w.fillRect(14.5, 2.8, 15.2, 3.4);
  w.fillRect(2.0, 8.0, 3.0, 8.6);
  w.fillRect(6.0, 7.0, 6.5, 7.5);
  w.fillRect(10.0, 8.2, 11.2, 8.8);
  w.fillRect(13.5, 7.2, 14.1, 7.8);
  w.fillRect(9.0, 4.8, 9.2, 5.0);
  return w;
}

std::vector<Pose2> officeTour() {
  return {{1.5, 5.0, 0.0},  {3.0, 5.0, 0.0},  {3.0, 2.0, 0.0},  {2.5, 3.0, 0.0},
          {3.0, 5.0, 0.0},  {8.0, 5.0, 0.0},  {8.0, 2.5, 0.0},  {8.0, 5.0, 0.0},
          {11.0, 5.0, 0.0}, {11.0, 8.0, 0.0}, {11.0, 5.0, 0.0}, {13.0, 5.0, 0.0},
          {13.0, 2.0, 0.0}, {13.0, 5.0, 0.0}, {14.5, 5.0, 0.0}, {5.0, 5.0, 0.0},
          {5.0, 8.0, 0.0},  {5.0, 5.0, 0.0},  {1.5, 5.0, 0.0}};
}

SyntheticRun simulateRun(const SyntheticWorld& world, const std::vector<Pose2>& waypoints,
                         const RunOptions& o) {
  SyntheticRun run;
  const double increment = o.beams > 1 ? o.fov / (o.beams - 1) : 0.0;
  run.laser = LaserGeometry::planar(Pose2(-0.087, 0.0125, 0.0), -o.fov / 2, increment, o.beams);
  std::mt19937 rng(o.seed);
  std::normal_distribution<double> unit(0.0, 1.0);
  const double dt = 1.0 / o.scan_rate;

  Pose2 truth = waypoints.empty() ? Pose2() : waypoints.front();
  Pose2 odom;  // odometry starts at zero wherever the robot is
  double stamp = 10.0;
  auto scanAndRecord = [&]() {
    SyntheticStep step{stamp, truth, odom, Ranges(static_cast<std::size_t>(o.beams))};
    const Pose2 origin = truth * Pose2(run.laser.origin.x, run.laser.origin.y, 0.0);
    for (int i = 0; i < o.beams; ++i) {
      double r = world.castRay(origin.x, origin.y, truth.theta + run.laser.beams[i].angle,
                               o.range_max);
      if (std::isfinite(r)) r += o.range_noise * unit(rng);
      step.ranges[i] = (r < o.range_min) ? std::numeric_limits<float>::quiet_NaN()
                                         : static_cast<float>(r);
    }
    run.steps.push_back(std::move(step));
    stamp += dt;
  };
  auto move = [&](double v, double w) {
    const Pose2 d(v * dt, 0.0, w * dt);
    truth = truth * d;
    const double lin = d.x * (1.0 + o.odom_scale_linear) + o.odom_noise_linear * std::fabs(d.x) * unit(rng);
    const double ang = d.theta * (1.0 + o.odom_scale_angular) +
                       o.odom_noise_angular * (std::fabs(d.theta) + 0.2 * std::fabs(d.x)) * unit(rng);
    odom = odom * Pose2(lin, 0.0, ang);
    scanAndRecord();
  };

  scanAndRecord();
  for (std::size_t k = 1; k < waypoints.size(); ++k) {
    const double gx = waypoints[k].x, gy = waypoints[k].y;
    // Plan the turn and the straight leg once, then execute them in whole steps.
    double turn = normalizeAngle(std::atan2(gy - truth.y, gx - truth.x) - truth.theta);
    double dist = std::hypot(gx - truth.x, gy - truth.y);
    while (std::fabs(turn) > 1e-9) {
      const double w = std::copysign(std::min(o.turn_rate, std::fabs(turn) / dt), turn);
      move(0.0, w);
      turn -= w * dt;
    }
    while (dist > 1e-9) {
      const double v = std::min(o.speed, dist / dt);
      move(v, 0.0);
      dist -= v * dt;
    }
  }
  return run;
}

}  // namespace gmapping_lite
