#include "gmapping_lite/param_table.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <type_traits>
#include <utility>

namespace gmapping_lite {

namespace {
template <typename T>
ParamEntry entry(const std::string& name, T SlamParams::*field, ParamBounds bounds) {
  bounds.whole = std::is_integral_v<T>;
  return {name, [field](const SlamParams& p) { return static_cast<double>(p.*field); },
          [field](SlamParams* p, double v) { p->*field = static_cast<T>(v); }, std::move(bounds)};
}
template <typename T>
ParamEntry matcher(const std::string& name, T MatcherParams::*field, ParamBounds bounds) {
  bounds.whole = std::is_integral_v<T>;
  return {name, [field](const SlamParams& p) { return static_cast<double>(p.matcher.*field); },
          [field](SlamParams* p, double v) { p->matcher.*field = static_cast<T>(v); },
          std::move(bounds)};
}
ParamEntry motion(const std::string& name, double MotionNoise::*field) {
  return {name, [field](const SlamParams& p) { return p.motion.*field; },
          [field](SlamParams* p, double v) { p->motion.*field = v; },
          {0, 10, false, "a noise factor in [0, 10]"}};
}
}  // namespace

// Each bound says what the filter needs, not what a world suits: counts and sizes are capped
// so memory stays bounded (particles each carry a map; see paramProblem for the map's size),
// probabilities lie in (0, 1), step sizes and noise are finite.
const std::vector<ParamEntry>& paramTable() {
  static const std::vector<ParamEntry> table = {
      entry("particles", &SlamParams::particles,
            {1, 1000, false, "a count in [1, 1000] (each particle holds a map)"}),
      entry("linearUpdate", &SlamParams::linear_update, {0, 1e6, false, "metres >= 0"}),
      entry("angularUpdate", &SlamParams::angular_update, {0, 1e6, false, "radians >= 0"}),
      entry("temporalUpdate", &SlamParams::temporal_update,
            {-1e6, 1e6, false, "seconds (< 0 turns it off)"}),
      entry("resampleThreshold", &SlamParams::resample_threshold,
            {0, 1, true, "a fraction in (0, 1]"}),
      entry("minimumScore", &SlamParams::minimum_score, {0, 1e9, false, "a score >= 0"}),
      entry("ogain", &SlamParams::ogain, {0, 1e6, true, "a gain > 0"}),
      entry("delta", &SlamParams::delta, {0.001, 10, false, "a cell size in [0.001, 10] m"}),
      entry("occ_thresh", &SlamParams::occ_thresh,
            {0, std::nextafter(1.0, 0.0), true, "a probability in (0, 1)"}),
      entry("xmin", &SlamParams::xmin, {-1e6, 1e6, false, "metres"}),
      entry("ymin", &SlamParams::ymin, {-1e6, 1e6, false, "metres"}),
      entry("xmax", &SlamParams::xmax, {-1e6, 1e6, false, "metres"}),
      entry("ymax", &SlamParams::ymax, {-1e6, 1e6, false, "metres"}),
      // not gmapping's: makes runs reproducible (an unsigned 32-bit seed)
      entry("seed", &SlamParams::seed, {0, 4294967295.0, false, "a whole number in [0, 4294967295]"}),
      // not gmapping's: the back end
      entry("loop_closure", &SlamParams::loop_closure, {0, 1, false, "0 or 1 (false or true)"}),
      matcher("sigma", &MatcherParams::sigma, {0, 1e3, true, "metres > 0"}),
      matcher("kernelSize", &MatcherParams::kernel_size, {0, 10, false, "cells in [0, 10]"}),
      matcher("lstep", &MatcherParams::lstep, {0, 10, true, "metres in (0, 10]"}),
      matcher("astep", &MatcherParams::astep, {0, 3.2, true, "radians in (0, pi]"}),
      matcher("iterations", &MatcherParams::iterations, {0, 100, false, "a count in [0, 100]"}),
      matcher("lsigma", &MatcherParams::lsigma, {0, 1e3, true, "a value > 0"}),
      matcher("lskip", &MatcherParams::lskip, {0, 1e4, false, "a count >= 0"}),
      matcher("maxRange", &MatcherParams::max_range, {0, 1e4, true, "metres in (0, 10000]"}),
      matcher("maxUrange", &MatcherParams::max_urange, {0, 1e4, true, "metres in (0, 10000]"}),
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
// The initial map's cells a side at most: 20 000 cells at 0.05 m is 1 km.
constexpr double kMaxCellsPerSide = 20000;

std::string shown(const std::string& name, double value, const std::string& rule) {
  std::ostringstream out;
  out << name << " is " << value << ": it must be " << rule;
  return out.str();
}
}  // namespace

std::string entryProblem(const ParamEntry& e, double v) {
  const ParamBounds& b = e.bounds;
  if (b.rule.empty()) return "";
  const bool above_lo = b.lo_open ? v > b.lo : v >= b.lo;
  if (!std::isfinite(v) || !above_lo || v > b.hi) return shown(e.name, v, b.rule);
  if (b.whole && v != std::floor(v)) return shown(e.name, v, "a whole number: " + b.rule);
  return "";
}

std::string valueProblem(const std::string& name, double value) {
  const auto& table = paramTable();
  const auto it = std::find_if(table.begin(), table.end(),
                               [&](const ParamEntry& e) { return e.name == name; });
  return it == table.end() ? "" : entryProblem(*it, value);
}

std::string paramProblem(const SlamParams& params, bool max_range_set, bool max_urange_set) {
  for (const ParamEntry& e : paramTable()) {
    if ((e.name == "maxRange" && !max_range_set) || (e.name == "maxUrange" && !max_urange_set)) continue;
    const std::string problem = entryProblem(e, e.get(params));
    if (!problem.empty()) return problem;
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

std::string rangeDefaults(SlamParams* params, double range_max, bool max_range_set,
                          bool max_urange_set) {
  std::string note;
  if (!max_range_set && !(range_max <= kMaxDefaultRange)) {  // NaN and inf included
    std::ostringstream out;
    out << "the scan's range_max " << range_max << " is beyond " << kMaxDefaultRange
        << " m; using maxRange " << kMaxDefaultRange
        << " m (set ~maxRange / ~maxUrange for a longer laser)";
    note = out.str();
    range_max = kMaxDefaultRange;
  }
  // Less 0.01 m, but never down to 0 for a laser whose range_max is a few centimetres.
  if (!max_range_set) params->matcher.max_range = std::max(range_max - 0.01, 0.5 * range_max);
  if (!max_urange_set) params->matcher.max_urange = params->matcher.max_range;
  return note;
}

}  // namespace gmapping_lite
