#include "gmapping_lite/param_table.h"

#include <algorithm>

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

void rangeDefaults(SlamParams* params, double range_max, bool max_range_set,
                   bool max_urange_set) {
  if (!max_range_set) params->matcher.max_range = range_max - 0.01;
  if (!max_urange_set) params->matcher.max_urange = params->matcher.max_range;
}

}  // namespace gmapping_lite
