#include "gmapping_lite/param_table.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace gmapping_lite {

namespace {
template <typename T>
ParamEntry entry(const std::string& name, T SlamParams::*field) {
  return {name, [field](const SlamParams& p) { return static_cast<double>(p.*field); },
          [field](SlamParams* p, double v) { p->*field = static_cast<T>(v); }};
}
template <typename T>
ParamEntry matcher(const std::string& name, T MatcherParams::*field) {
  return {name, [field](const SlamParams& p) { return static_cast<double>(p.matcher.*field); },
          [field](SlamParams* p, double v) { p->matcher.*field = static_cast<T>(v); }};
}
ParamEntry motion(const std::string& name, double MotionNoise::*field) {
  return {name, [field](const SlamParams& p) { return p.motion.*field; },
          [field](SlamParams* p, double v) { p->motion.*field = v; }};
}
}  // namespace

const std::vector<ParamEntry>& paramTable() {
  static const std::vector<ParamEntry> table = {
      entry("particles", &SlamParams::particles),
      entry("linearUpdate", &SlamParams::linear_update),
      entry("angularUpdate", &SlamParams::angular_update),
      entry("temporalUpdate", &SlamParams::temporal_update),
      entry("resampleThreshold", &SlamParams::resample_threshold),
      entry("minimumScore", &SlamParams::minimum_score),
      entry("ogain", &SlamParams::ogain),
      entry("delta", &SlamParams::delta),
      entry("occ_thresh", &SlamParams::occ_thresh),
      entry("xmin", &SlamParams::xmin),
      entry("ymin", &SlamParams::ymin),
      entry("xmax", &SlamParams::xmax),
      entry("ymax", &SlamParams::ymax),
      entry("seed", &SlamParams::seed),  // not gmapping's: makes runs reproducible
      entry("loop_closure", &SlamParams::loop_closure),  // not gmapping's: the back end
      matcher("sigma", &MatcherParams::sigma),
      matcher("kernelSize", &MatcherParams::kernel_size),
      matcher("lstep", &MatcherParams::lstep),
      matcher("astep", &MatcherParams::astep),
      matcher("iterations", &MatcherParams::iterations),
      matcher("lsigma", &MatcherParams::lsigma),
      matcher("lskip", &MatcherParams::lskip),
      matcher("maxRange", &MatcherParams::max_range),
      matcher("maxUrange", &MatcherParams::max_urange),
      motion("srr", &MotionNoise::srr),
      motion("srt", &MotionNoise::srt),
      motion("str", &MotionNoise::str),
      motion("stt", &MotionNoise::stt),
  };
  return table;
}

bool setParam(SlamParams* params, const std::string& name, double value) {
  const auto& table = paramTable();
  const auto it = std::find_if(table.begin(), table.end(),
                               [&](const ParamEntry& e) { return e.name == name; });
  if (it == table.end()) return false;
  it->set(params, value);
  return true;
}

namespace {
struct Rule {
  const char* name;
  double lo, hi;
  bool lo_open;  // lo itself not allowed
  const char* text;
};

// Each bound says what the filter needs, not what a world suits: counts and sizes are
// capped so memory stays bounded (particles each carry a map; a side of 20 000 cells at
// 0.05 m is 1 km), probabilities lie in (0, 1), step sizes and noise are finite.
const Rule kRules[] = {
    {"particles", 1, 1000, false, "a count in [1, 1000] (each particle holds a map)"},
    {"linearUpdate", 0, 1e6, false, "metres >= 0"},
    {"angularUpdate", 0, 1e6, false, "radians >= 0"},
    {"temporalUpdate", -1e6, 1e6, false, "seconds (< 0 turns it off)"},
    {"resampleThreshold", 0, 1, true, "a fraction in (0, 1]"},
    {"minimumScore", 0, 1e9, false, "a score >= 0"},
    {"ogain", 0, 1e6, true, "a gain > 0"},
    {"delta", 0.001, 10, false, "a cell size in [0.001, 10] m"},
    {"occ_thresh", 0, std::nextafter(1.0, 0.0), true, "a probability in (0, 1)"},
    {"xmin", -1e6, 1e6, false, "metres"},
    {"ymin", -1e6, 1e6, false, "metres"},
    {"xmax", -1e6, 1e6, false, "metres"},
    {"ymax", -1e6, 1e6, false, "metres"},
    {"sigma", 0, 1e3, true, "metres > 0"},
    {"kernelSize", 0, 10, false, "cells in [0, 10]"},
    {"lstep", 0, 10, true, "metres in (0, 10]"},
    {"astep", 0, 3.2, true, "radians in (0, pi]"},
    {"iterations", 0, 100, false, "a count in [0, 100]"},
    {"lsigma", 0, 1e3, true, "a value > 0"},
    {"lskip", 0, 1e4, false, "a count >= 0"},
    {"srr", 0, 10, false, "a noise factor in [0, 10]"},
    {"srt", 0, 10, false, "a noise factor in [0, 10]"},
    {"str", 0, 10, false, "a noise factor in [0, 10]"},
    {"stt", 0, 10, false, "a noise factor in [0, 10]"},
    {"maxRange", 0, 1e4, true, "metres in (0, 10000]"},
    {"maxUrange", 0, 1e4, true, "metres in (0, 10000]"},
};
constexpr double kMaxCellsPerSide = 20000;

std::string shown(const std::string& name, double value, const std::string& rule) {
  std::ostringstream out;
  out << name << " is " << value << ": it must be " << rule;
  return out.str();
}
}  // namespace

std::string paramProblem(const SlamParams& params, bool max_range_set, bool max_urange_set) {
  const auto& table = paramTable();
  for (const Rule& rule : kRules) {
    const std::string name = rule.name;
    if ((name == "maxRange" && !max_range_set) || (name == "maxUrange" && !max_urange_set)) continue;
    const auto it = std::find_if(table.begin(), table.end(),
                                 [&](const ParamEntry& e) { return e.name == name; });
    const double v = it->get(params);
    const bool above_lo = rule.lo_open ? v > rule.lo : v >= rule.lo;
    if (!std::isfinite(v) || !above_lo || v > rule.hi) return shown(name, v, rule.text);
  }
  if (!(params.xmin < params.xmax)) return shown("xmin", params.xmin, "below xmax");
  if (!(params.ymin < params.ymax)) return shown("ymin", params.ymin, "below ymax");
  const double side = std::max(params.xmax - params.xmin, params.ymax - params.ymin);
  if (side / params.delta > kMaxCellsPerSide) {
    return shown("delta", params.delta,
                 "large enough that the initial map (xmin..xmax, ymin..ymax) has at most 20000 cells a side");
  }
  return "";
}

void rangeDefaults(SlamParams* params, double range_max, bool max_range_set,
                   bool max_urange_set) {
  if (!max_range_set) params->matcher.max_range = range_max - 0.01;
  if (!max_urange_set) params->matcher.max_urange = params->matcher.max_range;
}

}  // namespace gmapping_lite
