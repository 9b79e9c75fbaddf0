#include "gmapping_lite/pose_fusion.h"

#include <Eigen/Dense>
#include <cmath>

namespace gmapping_lite {

namespace {
Eigen::Matrix3d toEigen(const double m[3][3]) {
  Eigen::Matrix3d e;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) e(i, j) = m[i][j];
  return e;
}

Covariance symmetric(const Eigen::Matrix3d& e) {
  Covariance c;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) c.m[i][j] = 0.5 * (e(i, j) + e(j, i));
  return c;
}
}  // namespace

Covariance propagate(const Covariance& cov, const Pose2& pose, const Pose2& increment,
                     double var_xy, double var_theta) {
  // x' = x + R(theta) t, theta' = theta + dtheta: d x' / d theta = R'(theta) t, the
  // increment's translation turned a quarter.
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  const double wx = c * increment.x - s * increment.y, wy = s * increment.x + c * increment.y;
  Eigen::Matrix3d f = Eigen::Matrix3d::Identity();
  f(0, 2) = -wy;
  f(1, 2) = wx;
  Eigen::Matrix3d p = f * toEigen(cov.m) * f.transpose();
  p(0, 0) += var_xy;
  p(1, 1) += var_xy;
  p(2, 2) += var_theta;
  return symmetric(p);
}

Pose2 fuse(const Pose2& predicted, const Covariance& prior, const Pose2& measured,
           const Information& info, Covariance* posterior) {
  // Posterior covariance (P^-1 + I)^-1 = (1 + P I)^-1 P and gain (1 + P I)^-1 P I: only
  // 1 + P I is inverted, and its eigenvalues are at least 1 (P I is similar to the positive
  // semi-definite P^1/2 I P^1/2).
  const Eigen::Matrix3d p = toEigen(prior.m), i = toEigen(info.m);
  const Eigen::Matrix3d a = Eigen::Matrix3d::Identity() + p * i;
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(a);
  if (!lu.isInvertible()) {
    *posterior = prior;
    return predicted;
  }
  const Eigen::Matrix3d post = lu.solve(p);
  const Eigen::Matrix3d gain = lu.solve(p * i);
  const Eigen::Vector3d innovation(measured.x - predicted.x, measured.y - predicted.y,
                                   normalizeAngle(measured.theta - predicted.theta));
  const Eigen::Vector3d step = gain * innovation;
  *posterior = symmetric(post);
  return Pose2(predicted.x + step(0), predicted.y + step(1),
               normalizeAngle(predicted.theta + step(2)));
}

}  // namespace gmapping_lite
