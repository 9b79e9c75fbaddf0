// The period at which odometry is published, from the stamps of its samples (the odom ->
// base transforms on /tf): the median of the recent intervals between consecutive distinct
// stamps. The median ignores a repeated stamp (the same sample sent twice), a gap (samples
// lost or the publisher paused) and the odd early sample, as long as they are fewer than half
// of the recent intervals.
#pragma once

#include <cstddef>
#include <deque>

namespace gmapping_lite {

class OdometryPeriod {
 public:
  // `window`: how many recent intervals the median is taken over (at least 1).
  explicit OdometryPeriod(std::size_t window = kDefaultWindow);

  // One odometry sample's stamp (s). A stamp equal to the last is the same sample again and
  // is ignored; a stamp before the last means time jumped back (a bag played again, a
  // simulator reset): what was learnt is forgotten and the counting starts again from it.
  void add(double stamp);

  // The median recent interval (s); 0 until two distinct stamps have been seen.
  double period() const;
  bool known() const { return !intervals_.empty(); }

  // Odd, so the median is one interval; 51 intervals are one to five seconds of odometry at
  // the usual 10-50 Hz: a change of rate is followed within seconds, and it takes 26 odd
  // intervals to move the median.
  static constexpr std::size_t kDefaultWindow = 51;

 private:
  std::size_t window_;
  std::deque<double> intervals_;  // the most recent last
  double last_ = 0.0;
  bool have_last_ = false;
};

}  // namespace gmapping_lite
