// Loop closure for the back end: the newest scan is matched against a map made of old scans
// taken nearby, over the window the trajectory's accumulated uncertainty allows. A match that
// most of the scan agrees with, and that no other place in the window rivals, joins the newest
// pose to the nearest old one.
#pragma once

#include <vector>

#include "gmapping_lite/pose_graph.h"
#include "gmapping_lite/scan_matcher.h"
#include "gmapping_lite/trajectory.h"

namespace gmapping_lite {

struct LoopClosureReport {
  bool tried = false;
  int candidates = 0;       // old nodes the scan was matched against
  double window_xy = 0.0;   // half-widths of the search (m, rad)
  double window_theta = 0.0;
  int matched = 0, contradicting = 0;
  double margin = 0.0;      // best score minus the best elsewhere in the window
  bool accepted = false;
};

class LoopCloser {
 public:
  // `matcher`: the filter's matching parameters (sigma, ranges, merging); `resolution`: the
  // map's cell size, the finest the search needs to step.
  LoopCloser(const MatcherParams& matcher, double resolution);

  // Look for a loop closure of the last node of `chain` (oldest first; node k has index k).
  // `loops` are the loop edges found so far (they shorten the uncertainty between the nodes
  // they join). Returns true and writes `edge` (from an old node to the last) when one is found.
  bool find(const std::vector<const TrajectoryNode*>& chain, const std::vector<PoseEdge>& loops,
            PoseEdge* edge, LoopClosureReport* report = nullptr);

 private:
  ScanMatcher matcher_;
  double resolution_;
  double max_range_;
};

// Variances (xy, theta) of the pose of each node relative to the last one, accumulated along
// the chain from the steps' information, shortened by the loop edges.
void relativeUncertainty(const std::vector<const TrajectoryNode*>& chain,
                         const std::vector<PoseEdge>& loops, std::vector<double>* var_xy,
                         std::vector<double>* var_theta);

}  // namespace gmapping_lite
