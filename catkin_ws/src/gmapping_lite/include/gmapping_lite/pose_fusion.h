// A particle's pose relative to its own map as a Gaussian carried from update to update (a
// Kalman filter per particle, on top of the particle filter's sampling of trajectories):
// - prediction: the pose moves by odometry's increment and its covariance grows by the
//   increment's motion-model covariance (plus the carried heading's lever on the position);
// - correction: the scan match is a measurement of the pose with its own information, and the
//   new pose is the information-weighted mean of prediction and match, the covariance the
//   posterior's.
// Where the scan knows little (open floor, far walls, along a corridor) the prediction wins;
// where the particle has drifted (a large carried covariance) the match wins.
// The state may carry odometry's two scale factors too (distance and turn; a wheel radius or
// track width off by a few percent): odometry's increment is scaled before it is applied, and
// the matches' corrections estimate the scales through their covariance with the pose.
#pragma once

#include <utility>

#include "gmapping_lite/pose2.h"
#include "gmapping_lite/pose_graph.h"

namespace gmapping_lite {

// Odometry's scale factors: the true increment is (distance x, y; rotation theta) times
// odometry's.
struct OdometryScale {
  double distance = 1.0, rotation = 1.0;
  // The scan match's own bias along the step, so that it is not taken for odometry's scale: `unknown_pull` metres per metre of step and unit share of end points in unmapped
  // space, `turn_pull` metres per radian of the step's turn.
  double unknown_pull = 0.0, turn_pull = 0.0;
};

// Where the match's bias acts in this update: the step's direction (world, unit) and the
// regressors of the two pulls (step length times the unknown share; |turn|).
struct MatchBiasRegressors {
  double ux = 0.0, uy = 0.0;
  double unknown_step = 0.0, turn = 0.0;
};

constexpr int kStates = 7;  // x, y, theta, distance scale, rotation scale, the two pulls

// A symmetric covariance over (x, y, theta, distance scale, rotation scale, unknown pull, turn
// pull), world frame (m^2, m rad, rad^2, ...). With the extra rows zero it is the pose's 3x3
// covariance alone.
struct Covariance {
  double m[kStates][kStates] = {};

  static Covariance diagonal(double xx, double yy, double tt, double dd = 0.0, double rr = 0.0,
                             double uu = 0.0, double vv = 0.0) {
    Covariance c;
    c.m[0][0] = xx;
    c.m[1][1] = yy;
    c.m[2][2] = tt;
    c.m[3][3] = dd;
    c.m[4][4] = rr;
    c.m[5][5] = uu;
    c.m[6][6] = vv;
    return c;
  }
  // The position's variance per axis (half the trace of the xy block) and the heading's.
  double varXY() const { return 0.5 * (m[0][0] + m[1][1]); }
  double varTheta() const { return m[2][2]; }
};

// `pose` moved by odometry's `increment` (robot frame) corrected by `scale`.
Pose2 predict(const Pose2& pose, const Pose2& increment, const OdometryScale& scale = {});

// The covariance of predict(pose, increment, scale) given the covariance of `pose` (and of the
// scales), plus the increment's own: isotropic var_xy in position and var_theta in heading
// (the motion model's spread for this increment). A heading error at `pose` swings the
// increment's translation (the Jacobian's lever), a scale error stretches it.
Covariance propagate(const Covariance& cov, const Pose2& pose, const Pose2& increment,
                     double var_xy, double var_theta, const OdometryScale& scale = {});

// The fusion of a prediction (`predicted`, covariance `prior`) with a measurement of the same
// pose (`measured`, information `info`, world frame): returns the posterior mean and writes its
// covariance; `scale`, when given, takes its share of the correction. Computed without
// inverting `prior` or `info`, so either may be singular (a prediction known exactly, a scan
// that pins nothing).
// `consistency`, when given, receives the innovation's normalised square (innovation' S^-1
// innovation, S = prior + info^-1 over what the scan observes) in `first` and its expectation
// if prior and info were right (the observed dimensions, at most 3) in `second`. `bias`, when
// given, says where the match's own pulls (the last two states) act in this update: the match
// is then a measurement of the pose plus those pulls.
Pose2 fuse(const Pose2& predicted, const Covariance& prior, const Pose2& measured,
           const Information& info, Covariance* posterior, OdometryScale* scale = nullptr,
           std::pair<double, double>* consistency = nullptr,
           const MatchBiasRegressors* bias = nullptr);

}  // namespace gmapping_lite
