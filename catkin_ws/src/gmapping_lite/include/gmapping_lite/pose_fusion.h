// A particle's pose relative to its own map as a Gaussian carried from update to update (a
// Kalman filter per particle, on top of the particle filter's sampling of trajectories):
// - prediction: the pose moves by odometry's increment and its covariance grows by the
//   increment's motion-model covariance (plus the carried heading's lever on the position);
// - correction: the scan match is a measurement of the pose with its own information, and the
//   new pose is the information-weighted mean of prediction and match, the covariance the
//   posterior's.
// Where the scan knows little (open floor, far walls, along a corridor) the prediction wins;
// where the particle has drifted (a large carried covariance) the match wins.
#pragma once

#include "gmapping_lite/pose2.h"
#include "gmapping_lite/pose_graph.h"

namespace gmapping_lite {

// A symmetric 3x3 covariance over (x, y, theta), world frame (m^2, m rad, rad^2).
struct Covariance {
  double m[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};

  static Covariance diagonal(double xx, double yy, double tt) {
    Covariance c;
    c.m[0][0] = xx;
    c.m[1][1] = yy;
    c.m[2][2] = tt;
    return c;
  }
  // The position's variance per axis (half the trace of the xy block) and the heading's.
  double varXY() const { return 0.5 * (m[0][0] + m[1][1]); }
  double varTheta() const { return m[2][2]; }
};

// The covariance of `pose` * `increment` (increment in the robot frame) given the covariance of
// `pose`, plus the increment's own: isotropic var_xy in position and var_theta in heading (the
// motion model's spread for this increment). A heading error at `pose` swings the increment's
// translation: the Jacobian's lever.
Covariance propagate(const Covariance& cov, const Pose2& pose, const Pose2& increment,
                     double var_xy, double var_theta);

// The fusion of a prediction (`predicted`, covariance `prior`) with a measurement of the same
// pose (`measured`, information `info`, world frame): returns the posterior mean and writes its
// covariance. Computed without inverting `prior` or `info`, so either may be singular (a
// prediction known exactly, a scan that pins nothing).
Pose2 fuse(const Pose2& predicted, const Covariance& prior, const Pose2& measured,
           const Information& info, Covariance* posterior);

}  // namespace gmapping_lite
