#include "gmapping_lite/pose_fusion.h"

#include <Eigen/Dense>
#include <cmath>

namespace gmapping_lite {

namespace {
using Matrix5 = Eigen::Matrix<double, kStates, kStates>;

Matrix5 toEigen(const Covariance& c) {
  Matrix5 e;
  for (int i = 0; i < kStates; ++i)
    for (int j = 0; j < kStates; ++j) e(i, j) = c.m[i][j];
  return e;
}

Covariance symmetric(const Matrix5& e) {
  Covariance c;
  for (int i = 0; i < kStates; ++i)
    for (int j = 0; j < kStates; ++j) c.m[i][j] = 0.5 * (e(i, j) + e(j, i));
  return c;
}
}  // namespace

Pose2 predict(const Pose2& pose, const Pose2& increment, const OdometryScale& scale) {
  return pose * Pose2(scale.distance * increment.x, scale.distance * increment.y,
                      scale.rotation * increment.theta);
}

Covariance propagate(const Covariance& cov, const Pose2& pose, const Pose2& increment,
                     double var_xy, double var_theta, const OdometryScale& scale) {
  // x' = x + R(theta) k_d t, theta' = theta + k_r dtheta: d x' / d theta = R'(theta) k_d t,
  // the increment's translation turned a quarter; d x' / d k_d = R(theta) t;
  // d theta' / d k_r = dtheta.
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  const double tx = c * increment.x - s * increment.y, ty = s * increment.x + c * increment.y;
  Matrix5 f = Matrix5::Identity();
  f(0, 2) = -scale.distance * ty;
  f(1, 2) = scale.distance * tx;
  f(0, 3) = tx;
  f(1, 3) = ty;
  f(2, 4) = increment.theta;
  Matrix5 p = f * toEigen(cov) * f.transpose();
  p(0, 0) += var_xy;
  p(1, 1) += var_xy;
  p(2, 2) += var_theta;
  return symmetric(p);
}

Pose2 fuse(const Pose2& predicted, const Covariance& prior, const Pose2& measured,
           const Information& info, Covariance* posterior, OdometryScale* scale,
           std::pair<double, double>* consistency, const MatchBiasRegressors* bias) {
  // The measurement sees the pose only (H = [1 0]). Gain K = P H' (H P H' + I^-1)^-1 =
  // P H' (1 + I H P H')^-1 I: only 1 + I H P H' is inverted, and its eigenvalues are at least 1
  // (I H P H' is similar to a positive semi-definite matrix).
  const Matrix5 p = toEigen(prior);
  if (consistency) *consistency = {0.0, 0.0};
  Eigen::Matrix3d i;
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) i(r, k) = info.m[r][k];
  // H = [1 0 h]: the match sees the pose plus its own pulls along the step.
  Eigen::Matrix<double, 3, kStates> h = Eigen::Matrix<double, 3, kStates>::Zero();
  h.leftCols<3>() = Eigen::Matrix3d::Identity();
  double pull_x = 0.0, pull_y = 0.0;
  if (bias && scale) {
    h(0, 5) = bias->ux * bias->unknown_step;
    h(1, 5) = bias->uy * bias->unknown_step;
    h(0, 6) = bias->ux * bias->turn;
    h(1, 6) = bias->uy * bias->turn;
    pull_x = h(0, 5) * scale->unknown_pull + h(0, 6) * scale->turn_pull;
    pull_y = h(1, 5) * scale->unknown_pull + h(1, 6) * scale->turn_pull;
  }
  const Eigen::Matrix<double, kStates, 3> pht = p * h.transpose();
  const Eigen::Matrix3d hph = h * pht;
  const Eigen::Matrix3d a = Eigen::Matrix3d::Identity() + i * hph;
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(a);
  if (!lu.isInvertible()) {
    *posterior = prior;
    return predicted;
  }
  const Eigen::Matrix<double, kStates, 3> gain = pht * lu.solve(i);
  const Eigen::Vector3d innovation(measured.x - predicted.x - pull_x,
                                   measured.y - predicted.y - pull_y,
                                   normalizeAngle(measured.theta - predicted.theta));
  const Eigen::Matrix<double, kStates, 1> step = gain * innovation;
  if (consistency) {
    // S^-1 = (1 + I P)^-1 I. With the innovation ~ N(0, P + I^-1) on I's range, E[nu' S^-1 nu]
    // = tr((1 + I P)^-1 (I P + Pi)), Pi the projector on I's range (3 where I is regular).
    const Eigen::Matrix3d s_inv = lu.solve(i);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(i);
    const double top = eig.eigenvalues().maxCoeff();
    Eigen::Matrix3d range = Eigen::Matrix3d::Zero();
    for (int k = 0; k < 3; ++k)
      if (eig.eigenvalues()(k) > 1e-9 * top)
        range += eig.eigenvectors().col(k) * eig.eigenvectors().col(k).transpose();
    consistency->first = innovation.dot(s_inv * innovation);
    consistency->second = lu.solve(i * hph + range).trace();
  }
  *posterior = symmetric((Matrix5::Identity() - gain * h) * p);
  if (scale) {
    scale->distance += step(3);
    scale->rotation += step(4);
    scale->unknown_pull += step(5);
    scale->turn_pull += step(6);
  }
  return Pose2(predicted.x + step(0), predicted.y + step(1),
               normalizeAngle(predicted.theta + step(2)));
}

}  // namespace gmapping_lite
