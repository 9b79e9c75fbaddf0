#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "gmapping_lite/loop_closure.h"

using namespace gmapping_lite;  // NOLINT: test file

namespace {

// A chain of nodes at `poses`, each step with the given standard deviations.
std::vector<std::shared_ptr<TrajectoryNode>> makeChain(const std::vector<Pose2>& poses,
                                                       double sigma_xy, double sigma_theta) {
  std::vector<std::shared_ptr<TrajectoryNode>> nodes;
  for (std::size_t k = 0; k < poses.size(); ++k) {
    auto n = std::make_shared<TrajectoryNode>();
    n->pose = poses[k];
    n->index = static_cast<int>(k);
    if (k > 0) {
      n->parent = nodes.back();
      n->step = poses[k].relativeTo(poses[k - 1]);
      n->information = Information::diagonal(1.0 / (sigma_xy * sigma_xy),
                                             1.0 / (sigma_xy * sigma_xy),
                                             1.0 / (sigma_theta * sigma_theta));
    }
    nodes.push_back(n);
  }
  return nodes;
}

std::vector<const TrajectoryNode*> raw(const std::vector<std::shared_ptr<TrajectoryNode>>& nodes) {
  std::vector<const TrajectoryNode*> out;
  for (const auto& n : nodes) out.push_back(n.get());
  return out;
}

}  // namespace

// A loop edge whose scan pinned only one direction (its information nearly rank one, as a
// closure on a few collinear points gives: this matrix is one measured on ring_1) must leave
// the chain's own uncertainty as it is: never a negative variance, whose square root made
// every later search window NaN.
TEST(RelativeUncertainty, NearlySingularLoopEdgeLeavesTheChainAlone) {
  std::vector<Pose2> poses;
  for (int k = 0; k < 6; ++k) poses.emplace_back(0.5 * k, 0.0, 0.0);
  const auto nodes = makeChain(poses, 0.01, 0.01);
  std::vector<double> chain_xy, chain_theta;
  relativeUncertainty(raw(nodes), {}, &chain_xy, &chain_theta);

  PoseEdge edge;
  edge.from = 0;
  edge.to = 5;
  edge.measurement = poses[5];
  const double m[3][3] = {{1301.34, 4432.67, 6538.49},
                          {4432.67, 15098.7, 22271.6},
                          {6538.49, 22271.6, 32883.6}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) edge.information.m[i][j] = m[i][j];
  std::vector<double> var_xy, var_theta;
  relativeUncertainty(raw(nodes), {edge}, &var_xy, &var_theta);
  for (std::size_t k = 0; k < poses.size(); ++k) {
    EXPECT_GE(var_xy[k], 0.0) << "node " << k;
    EXPECT_GE(var_theta[k], 0.0) << "node " << k;
    EXPECT_FALSE(std::isnan(var_xy[k]) || std::isnan(var_theta[k])) << "node " << k;
    // The edge pins no position: the chain's figure stands.
    EXPECT_NEAR(var_xy[k], chain_xy[k], 1e-9) << "node " << k;
  }
}

// A well-conditioned loop edge is a shortcut: the old end becomes as certain as the edge.
TEST(RelativeUncertainty, LoopEdgeShortensTheChain) {
  std::vector<Pose2> poses;
  for (int k = 0; k < 20; ++k) poses.emplace_back(0.5 * k, 0.0, 0.0);
  const auto nodes = makeChain(poses, 0.01, 0.01);
  PoseEdge edge;
  edge.from = 0;
  edge.to = 19;
  edge.measurement = poses[19];
  edge.information = Information::diagonal(1e4, 1e4, 1e4);  // 1 cm, 0.01 rad
  std::vector<double> chain_xy, chain_theta, var_xy, var_theta;
  relativeUncertainty(raw(nodes), {}, &chain_xy, &chain_theta);
  relativeUncertainty(raw(nodes), {edge}, &var_xy, &var_theta);
  EXPECT_GT(chain_xy[0], 10 * 1e-4);  // the chain alone: 19 steps and their lever arms
  EXPECT_NEAR(var_xy[0], 1e-4, 1e-12);
  EXPECT_NEAR(var_theta[0], 1e-4, 1e-12);
}

// A turn on the spot whose heading no scan constrained (an infinite heading variance) has no
// lever arm: the positions stay finite, and nothing is NaN.
TEST(RelativeUncertainty, UnconstrainedTurnOnTheSpotIsNoNaN) {
  const std::vector<Pose2> poses = {{0, 0, 0}, {0, 0, 0.5}, {0, 0, 1.0}};
  auto nodes = makeChain(poses, 0.01, 0.01);
  nodes[2]->information = Information::diagonal(1e4, 1e4, 0.0);  // heading unconstrained
  std::vector<double> var_xy, var_theta;
  relativeUncertainty(raw(nodes), {}, &var_xy, &var_theta);
  for (std::size_t k = 0; k < poses.size(); ++k) {
    EXPECT_FALSE(std::isnan(var_xy[k]) || std::isnan(var_theta[k])) << "node " << k;
    EXPECT_TRUE(std::isfinite(var_xy[k])) << "node " << k;
  }
  EXPECT_TRUE(std::isinf(var_theta[0]));
}

// An information of exact rank one (a closure on points along one wall pins one direction
// only) gives no NaN and no negative variance: the other directions are unconstrained.
TEST(RelativeUncertainty, RankOneLoopEdgeIsNoNaN) {
  std::vector<Pose2> poses;
  for (int k = 0; k < 6; ++k) poses.emplace_back(0.5 * k, 0.0, 0.1 * k);
  const auto nodes = makeChain(poses, 0.02, 0.02);
  PoseEdge edge;
  edge.from = 0;
  edge.to = 5;
  edge.measurement = poses[5];
  const double v[3] = {0.6, 0.8, 0.0};  // pins position along (0.6, 0.8) only
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) edge.information.m[i][j] = 1e4 * v[i] * v[j];
  std::vector<double> var_xy, var_theta;
  relativeUncertainty(raw(nodes), {edge}, &var_xy, &var_theta);
  for (std::size_t k = 0; k < poses.size(); ++k) {
    EXPECT_FALSE(std::isnan(var_xy[k]) || std::isnan(var_theta[k])) << "node " << k;
    EXPECT_GE(var_xy[k], 0.0) << "node " << k;
    EXPECT_GE(var_theta[k], 0.0) << "node " << k;
  }
}
