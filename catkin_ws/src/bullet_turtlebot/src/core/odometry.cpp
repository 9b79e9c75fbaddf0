#include "bullet_turtlebot/odometry.hpp"

#include <cmath>

#include "bullet_turtlebot/diff_drive.hpp"

namespace bullet_turtlebot {

OdometryModel::OdometryModel(const OdometryNoise& noise, std::uint64_t seed) : noise_(noise), rng_(seed) {}

void OdometryModel::update(double forward, double rotation, double dt) {
  double f = forward, r = rotation;
  if (noise_.enabled && (forward != 0.0 || rotation != 0.0)) {
    // Random walks: variance proportional to |distance| so the drift does not depend on the
    // step size; nothing is drawn (and nothing moves) at rest.
    const double af = std::abs(forward), ar = std::abs(rotation);
    f += noise_.linear * std::sqrt(af) * gauss_(rng_);
    r = rotation * (1.0 + noise_.yaw_scale) +
        std::sqrt(noise_.angular * noise_.angular * ar +
                  noise_.angular_per_linear * noise_.angular_per_linear * af) *
            gauss_(rng_);
  }
  travelled_ += std::abs(forward);
  turned_ += std::abs(rotation);
  if (dt > 0) {
    v_ = f / dt;
    w_ = r / dt;
    pose_ = integrate_arc(pose_, v_, w_, dt);
  }
}

}  // namespace bullet_turtlebot
