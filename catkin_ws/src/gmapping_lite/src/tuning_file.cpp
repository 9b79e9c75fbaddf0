#include "gmapping_lite/tuning_file.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>

#include "gmapping_lite/param_table.h"

namespace gmapping_lite {

const std::vector<std::string>& nodeParamNames() {
  static const std::vector<std::string> names = {
      "base_frame",          "map_frame",  "odom_frame",  "throttle_scans",
      "map_update_interval", "transform_publish_period", "tf_wait", "tilt_tolerance"};
  return names;
}

std::vector<std::string> unusedParams(const std::vector<std::string>& names) {
  const auto& table = paramTable();
  const auto& node = nodeParamNames();
  std::vector<std::string> unused;
  for (const std::string& name : names) {
    const bool in_table = std::any_of(table.begin(), table.end(),
                                      [&](const ParamEntry& e) { return e.name == name; });
    if (!in_table && std::find(node.begin(), node.end(), name) == node.end())
      unused.push_back(name);
  }
  return unused;
}

std::string loadTuning(const std::string& path, SlamParams* params) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    return path + ": cannot read the tuning file: " + e.what();
  }
  if (!root.IsMap()) return path + ": the tuning file is not a map of parameter names to values";
  std::vector<std::string> names;
  for (const auto& item : root) names.push_back(item.first.Scalar());
  const auto unused = unusedParams(names);
  if (!unused.empty()) return path + ": " + unused.front() + " is not a slam_gmapping parameter";
  const auto& node = nodeParamNames();
  for (const auto& item : root) {
    const std::string& name = item.first.Scalar();
    if (std::find(node.begin(), node.end(), name) != node.end()) continue;
    double value = 0;
    try {
      value = item.second.as<double>();
    } catch (const YAML::Exception&) {
      return path + ": " + name + " must be a number";
    }
    const std::string problem = valueProblem(name, value);
    if (!problem.empty()) return path + ": " + problem;
    setParam(params, name, value);
  }
  const bool max_range_set = std::count(names.begin(), names.end(), "maxRange") > 0;
  const bool max_urange_set = std::count(names.begin(), names.end(), "maxUrange") > 0;
  const std::string problem = paramProblem(*params, max_range_set, max_urange_set);
  return problem.empty() ? "" : path + ": " + problem;
}

}  // namespace gmapping_lite
