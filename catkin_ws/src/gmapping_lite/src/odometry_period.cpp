#include "gmapping_lite/odometry_period.h"

#include <algorithm>
#include <vector>

namespace gmapping_lite {

OdometryPeriod::OdometryPeriod(std::size_t window) : window_(std::max<std::size_t>(1, window)) {}

void OdometryPeriod::add(double stamp) {
  if (have_last_ && stamp == last_) return;
  if (have_last_ && stamp < last_) {
    intervals_.clear();
  } else if (have_last_) {
    intervals_.push_back(stamp - last_);
    if (intervals_.size() > window_) intervals_.pop_front();
  }
  last_ = stamp;
  have_last_ = true;
}

double OdometryPeriod::period() const {
  if (intervals_.empty()) return 0.0;
  std::vector<double> sorted(intervals_.begin(), intervals_.end());
  const auto mid = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
  std::nth_element(sorted.begin(), mid, sorted.end());
  if (sorted.size() % 2) return *mid;
  // An even count (fewer intervals than the window so far): the mean of the middle two.
  const double upper = *mid;
  const double lower = *std::max_element(sorted.begin(), mid);
  return 0.5 * (lower + upper);
}

}  // namespace gmapping_lite
