// A 2-D pose graph: poses joined by relative-pose measurements with their information, solved
// by Gauss-Newton (sparse Cholesky) with the first pose held fixed. The back end of the filter:
// consecutive poses of the best particle are joined by what the scan matcher made of each
// step, and a loop closure joins a pose to an old one it re-observed.
#pragma once

#include <vector>

#include "gmapping_lite/pose2.h"

namespace gmapping_lite {

// A symmetric 3x3 information matrix over (x, y, theta).
struct Information {
  double m[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};

  static Information diagonal(double xx, double yy, double tt) {
    Information i;
    i.m[0][0] = xx;
    i.m[1][1] = yy;
    i.m[2][2] = tt;
    return i;
  }
  // The same information expressed in a frame rotated by `angle` (x' = R(angle)^T x).
  Information rotated(double angle) const;
};

struct PoseEdge {
  int from = 0, to = 0;
  Pose2 measurement;  // pose of `to` in the frame of `from`
  Information information;  // of the measurement, in the frame of `from`
};

class PoseGraph {
 public:
  int addNode(const Pose2& pose) {
    poses_.push_back(pose);
    return static_cast<int>(poses_.size()) - 1;
  }
  void addEdge(const PoseEdge& edge) { edges_.push_back(edge); }

  int size() const { return static_cast<int>(poses_.size()); }
  const Pose2& pose(int i) const { return poses_[static_cast<std::size_t>(i)]; }
  const std::vector<Pose2>& poses() const { return poses_; }
  const std::vector<PoseEdge>& edges() const { return edges_; }

  // Squared Mahalanobis error of one edge at the current poses.
  double chi2(const PoseEdge& edge) const;
  double totalChi2() const;

  // Gauss-Newton with poses_[0] fixed, until the update is below a micrometre / microradian or
  // after `iterations`; returns the final total chi2.
  double optimize(int iterations = 10);

 private:
  std::vector<Pose2> poses_;
  std::vector<PoseEdge> edges_;
};

}  // namespace gmapping_lite
