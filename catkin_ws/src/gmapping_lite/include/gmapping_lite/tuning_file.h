// slam_gmapping's parameter names as a whole (the filter's table and the node's own), and the
// tuning file (config/turtlebot.yaml) that programs without a parameter server read.
#pragma once

#include <string>
#include <vector>

#include "gmapping_lite/slam_params.h"

namespace gmapping_lite {

// slam_gmapping's private parameters that are not the filter's (paramTable): frames,
// publishing and waits. SlamGmappingNode (src/slam_gmapping_node.cpp) reads each of them.
const std::vector<std::string>& nodeParamNames();

// Those of `names` (private parameter names, without "~") that slam_gmapping reads neither
// from paramTable nor nodeParamNames, in the order given.
std::vector<std::string> unusedParams(const std::vector<std::string>& names);

// Apply a tuning file, a YAML map of slam_gmapping's private parameter names to values, to
// *params: every filter parameter it names (the node's own, such as frames, are skipped).
// Returns "" or one line naming the file and what is wrong with it: unreadable, not a map, a
// value that is not a number, a name slam_gmapping does not read, or a value the filter
// cannot work with (paramProblem).
std::string loadTuning(const std::string& path, SlamParams* params);

}  // namespace gmapping_lite
