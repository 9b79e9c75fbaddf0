// A particle's trajectory: one node per processed scan, each pointing to its predecessor, so
// particles that descend from one ancestor share the nodes before they parted. A node keeps
// its scan (shared, not copied), so the back end can match it again and rebuild the map, and
// the step that led to it as the front end estimated it, with that estimate's information.
#pragma once

#include <memory>
#include <vector>

#include "gmapping_lite/laser.h"
#include "gmapping_lite/pose2.h"
#include "gmapping_lite/pose_graph.h"

namespace gmapping_lite {

struct TrajectoryNode {
  Pose2 pose;
  double stamp = 0.0;
  std::shared_ptr<const TrajectoryNode> parent;
  int index = 0;  // processed scans before this one (the root is 0)
  std::shared_ptr<const LaserGeometry> laser;
  std::shared_ptr<const Ranges> ranges;
  Pose2 step;               // this pose in the parent's frame, as the front end placed it
  Information information;  // of `step`, in the parent's frame
};

// The nodes from the root to `last`, oldest first.
inline std::vector<const TrajectoryNode*> chainOf(const TrajectoryNode* last) {
  std::vector<const TrajectoryNode*> chain;
  for (const TrajectoryNode* n = last; n; n = n->parent.get()) chain.push_back(n);
  return std::vector<const TrajectoryNode*>(chain.rbegin(), chain.rend());
}

}  // namespace gmapping_lite
