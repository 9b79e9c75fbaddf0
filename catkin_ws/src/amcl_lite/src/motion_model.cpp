#include "amcl_lite/motion_model.h"

#include <algorithm>
#include <cmath>

namespace amcl_lite {
namespace {

double gaussian(std::mt19937& rng, double sigma) {
  if (!(sigma > 0.0)) return 0.0;
  return std::normal_distribution<double>(0.0, sigma)(rng);
}

}  // namespace

Pose2 sampleDiffMotion(const Pose2& pose, const Pose2& old_odom, const Pose2& new_odom,
                       const OdomNoise& n, std::mt19937& rng) {
  const double dx = new_odom.x - old_odom.x, dy = new_odom.y - old_odom.y;
  const double trans = std::hypot(dx, dy);
  // Below a centimetre the direction of travel is noise; treat the step as a pure turn.
  const double rot1 = trans < 0.01 ? 0.0 : normalizeAngle(std::atan2(dy, dx) - old_odom.theta);
  const double rot2 = normalizeAngle(new_odom.theta - old_odom.theta - rot1);
  // Driving backwards is a rotation of about pi by this decomposition; as amcl does, take the
  // smaller of the two readings so reversing does not count as a half turn of noise.
  const double rot1_noise = std::min(std::fabs(rot1), std::fabs(normalizeAngle(rot1 - M_PI)));
  const double rot2_noise = std::min(std::fabs(rot2), std::fabs(normalizeAngle(rot2 - M_PI)));
  const double rot1_hat =
      rot1 - gaussian(rng, std::sqrt(n.alpha1 * rot1_noise * rot1_noise + n.alpha2 * trans * trans));
  const double trans_hat =
      trans - gaussian(rng, std::sqrt(n.alpha3 * trans * trans +
                                      n.alpha4 * (rot1_noise * rot1_noise + rot2_noise * rot2_noise)));
  const double rot2_hat =
      rot2 - gaussian(rng, std::sqrt(n.alpha1 * rot2_noise * rot2_noise + n.alpha2 * trans * trans));
  return Pose2(pose.x + trans_hat * std::cos(pose.theta + rot1_hat),
               pose.y + trans_hat * std::sin(pose.theta + rot1_hat),
               normalizeAngle(pose.theta + rot1_hat + rot2_hat));
}

}  // namespace amcl_lite
