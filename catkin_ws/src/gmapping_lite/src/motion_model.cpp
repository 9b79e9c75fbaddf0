#include "gmapping_lite/motion_model.h"

#include <cmath>

namespace gmapping_lite {

namespace {
double gaussian(double sigma, std::mt19937& rng) {
  if (sigma <= 0.0) return 0.0;
  return std::normal_distribution<double>(0.0, sigma)(rng);
}
}  // namespace

Pose2 MotionModel::sample(const Pose2& pose, const Pose2& old_odom, const Pose2& new_odom,
                          std::mt19937& rng) const {
  const Pose2 d = new_odom.relativeTo(old_odom);
  const double sxy = 0.3 * noise_.srr;  // gmapping's cross-axis coupling
  const double adx = std::fabs(d.x), ady = std::fabs(d.y), adt = std::fabs(d.theta);
  Pose2 noisy = d;
  noisy.x += gaussian(noise_.srr * adx + noise_.str * adt + sxy * ady, rng);
  noisy.y += gaussian(noise_.srr * ady + noise_.str * adt + sxy * adx, rng);
  noisy.theta = normalizeAngle(
      noisy.theta + gaussian(noise_.stt * adt + noise_.srt * std::hypot(d.x, d.y), rng));
  return pose * noisy;
}

}  // namespace gmapping_lite
