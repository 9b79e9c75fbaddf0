#include "gmapping_lite/pose_graph.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <cmath>

namespace gmapping_lite {

Information Information::rotated(double angle) const {
  // M' = T^T M T, T = blockdiag(R(angle), 1).
  const double c = std::cos(angle), s = std::sin(angle);
  const double t[3][3] = {{c, -s, 0}, {s, c, 0}, {0, 0, 1}};
  double mt[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      mt[i][j] = 0.0;
      for (int k = 0; k < 3; ++k) mt[i][j] += m[i][k] * t[k][j];
    }
  Information out;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      out.m[i][j] = 0.0;
      for (int k = 0; k < 3; ++k) out.m[i][j] += t[k][i] * mt[k][j];
    }
  return out;
}

namespace {

// Error of an edge (the relative pose's offset from the measurement, in the frame of `from`)
// and its Jacobians with respect to the two poses.
struct Linearised {
  double e[3];
  double ja[3][3];  // d e / d (x_from, y_from, theta_from)
  double jb[3][3];  // d e / d (x_to, y_to, theta_to)
};

Linearised linearise(const Pose2& a, const Pose2& b, const Pose2& z) {
  const double c = std::cos(a.theta), s = std::sin(a.theta);
  const double dx = b.x - a.x, dy = b.y - a.y;
  Linearised l;
  l.e[0] = c * dx + s * dy - z.x;
  l.e[1] = -s * dx + c * dy - z.y;
  l.e[2] = normalizeAngle(b.theta - a.theta - z.theta);
  const double ja[3][3] = {{-c, -s, -s * dx + c * dy}, {s, -c, -c * dx - s * dy}, {0, 0, -1}};
  const double jb[3][3] = {{c, s, 0}, {-s, c, 0}, {0, 0, 1}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      l.ja[i][j] = ja[i][j];
      l.jb[i][j] = jb[i][j];
    }
  return l;
}

}  // namespace

double PoseGraph::chi2(const PoseEdge& edge) const {
  const Linearised l = linearise(pose(edge.from), pose(edge.to), edge.measurement);
  double total = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) total += l.e[i] * edge.information.m[i][j] * l.e[j];
  return total;
}

double PoseGraph::totalChi2() const {
  double total = 0.0;
  for (const PoseEdge& e : edges_) total += chi2(e);
  return total;
}

double PoseGraph::optimize(int iterations) {
  const int n = size();
  if (n < 2 || edges_.empty()) return totalChi2();
  const int vars = 3 * (n - 1);  // pose 0 is held fixed
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(edges_.size() * 36 + static_cast<std::size_t>(vars));
  Eigen::VectorXd b(vars);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  bool analysed = false;
  for (int iteration = 0; iteration < iterations; ++iteration) {
    triplets.clear();
    b.setZero();
    for (const PoseEdge& edge : edges_) {
      const Linearised l = linearise(pose(edge.from), pose(edge.to), edge.measurement);
      const double(*o)[3] = edge.information.m;
      // J^T O for each side.
      const double(*jac[2])[3] = {l.ja, l.jb};
      const int node[2] = {edge.from, edge.to};
      double jto[2][3][3];
      for (int side = 0; side < 2; ++side)
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) {
            double v = 0.0;
            for (int k = 0; k < 3; ++k) v += jac[side][k][r] * o[k][c];
            jto[side][r][c] = v;
          }
      for (int s1 = 0; s1 < 2; ++s1) {
        if (node[s1] == 0) continue;
        const int row0 = 3 * (node[s1] - 1);
        for (int r = 0; r < 3; ++r) {
          double g = 0.0;
          for (int k = 0; k < 3; ++k) g += jto[s1][r][k] * l.e[k];
          b[row0 + r] += g;
        }
        for (int s2 = 0; s2 < 2; ++s2) {
          if (node[s2] == 0) continue;
          const int col0 = 3 * (node[s2] - 1);
          for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) {
              double v = 0.0;
              for (int k = 0; k < 3; ++k) v += jto[s1][r][k] * jac[s2][k][c];
              triplets.emplace_back(row0 + r, col0 + c, v);
            }
        }
      }
    }
    // A whisper of damping keeps poses that no edge reaches (none should) solvable.
    for (int i = 0; i < vars; ++i) triplets.emplace_back(i, i, 1e-9);
    Eigen::SparseMatrix<double> h(vars, vars);
    h.setFromTriplets(triplets.begin(), triplets.end());
    if (!analysed) {
      solver.analyzePattern(h);
      analysed = true;
    }
    solver.factorize(h);
    if (solver.info() != Eigen::Success) break;
    const Eigen::VectorXd step = solver.solve(-b);
    if (solver.info() != Eigen::Success) break;
    double largest_xy = 0.0, largest_theta = 0.0;
    for (int i = 1; i < n; ++i) {
      Pose2& p = poses_[static_cast<std::size_t>(i)];
      const int k = 3 * (i - 1);
      p.x += step[k];
      p.y += step[k + 1];
      p.theta = normalizeAngle(p.theta + step[k + 2]);
      largest_xy = std::max(largest_xy, std::hypot(step[k], step[k + 1]));
      largest_theta = std::max(largest_theta, std::fabs(step[k + 2]));
    }
    if (largest_xy < 1e-6 && largest_theta < 1e-6) break;
  }
  return totalChi2();
}

}  // namespace gmapping_lite
