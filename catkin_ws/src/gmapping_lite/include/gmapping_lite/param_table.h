// slam_gmapping's private parameter names, mapped onto SlamParams. Shared by the live node
// (which reads them from the parameter server) and slam_offline (name=value arguments).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "gmapping_lite/slam_params.h"

namespace gmapping_lite {

// What values a parameter may take; `rule` (empty: any value) says so in words.
struct ParamBounds {
  double lo = 0, hi = 0;
  bool lo_open = false;  // lo itself not allowed
  std::string rule;
  bool whole = false;  // an integer or boolean field: a fraction would be cut (2.5 particles: 2)
};

struct ParamEntry {
  std::string name;
  std::function<double(const SlamParams&)> get;
  std::function<void(SlamParams*, double)> set;
  ParamBounds bounds;
};

// Every numeric parameter of the filter. maxRange / maxUrange are included; when they are not
// set they come from the first scan's range_max (see rangeDefaults).
const std::vector<ParamEntry>& paramTable();

// Set one parameter by name; false if the name is unknown.
bool setParam(SlamParams* params, const std::string& name, double value);

// The problem with giving parameter `name` the value `value`, checked before it is stored (an
// integer field cannot hold 2.5, -1 or 1e300 to be checked afterwards): "NAME is VALUE: it
// must be RULE", or empty when it is usable or the name is unknown.
std::string valueProblem(const std::string& name, double value);

// The same check for an entry already in hand (no search of the table by name).
std::string entryProblem(const ParamEntry& e, double value);

// The first parameter the filter cannot work with, as "NAME is VALUE: it must be RULE"; empty
// when all are usable. maxRange / maxUrange are checked only when set (see rangeDefaults).
std::string paramProblem(const SlamParams& params, bool max_range_set, bool max_urange_set);

// The largest range_max the defaults below take from a scan (m): 80 m, gmapping's old maxUrange
// default, far beyond the book's lasers (the Turtlebot's Kinect scan reaches a few metres, the
// simulator's 8 m, the PR2's base laser 30 m). A driver reporting 1e4, 1e30 or inf for "no
// limit" would otherwise make every "no return" beam clear space out that far, and the grid
// grown to hold it exhaust memory (1e30 m overflows the cell index; the node never finished
// its first scan). Memory still grows with range: see README ("Lasers and bad input").
constexpr double kMaxDefaultRange = 80.0;

// gmapping's defaults from a scan: maxRange = range_max - 0.01 (so "no return" readings at
// range_max clear space), maxUrange = maxRange, each only if not set explicitly. A range_max
// above kMaxDefaultRange (or not finite) counts as kMaxDefaultRange; the return value then
// says so in one line (empty otherwise), for the caller to warn once.
std::string rangeDefaults(SlamParams* params, double range_max, bool max_range_set,
                          bool max_urange_set);

}  // namespace gmapping_lite
