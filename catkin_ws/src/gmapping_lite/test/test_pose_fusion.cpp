#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "gmapping_lite/pose_fusion.h"
#include "gmapping_lite/scan_matcher.h"
#include "synthetic.h"

using namespace gmapping_lite;  // NOLINT: test file

namespace {
struct Scene {
  SyntheticWorld world;
  RunOptions options;
  LaserGeometry laser;
  MatcherParams params;

  explicit Scene(SyntheticWorld w) : world(std::move(w)) {
    options.range_noise = 0.0;
    params.merge_distance = 0.05;  // as the filter sets it: the map's resolution
  }
  Ranges scanAt(const Pose2& pose) {
    SyntheticRun run = simulateRun(world, {pose}, options);
    laser = run.laser;
    return run.steps.front().ranges;
  }
  // A map drawn from scans at `pose` turned a little either way, as the filter draws one.
  GridMap mapAround(const Pose2& pose) {
    GridMap map(0.05);
    for (double a = -0.4; a <= 0.41; a += 0.2) {
      const Pose2 p(pose.x, pose.y, pose.theta + a);
      registerScan(&map, p, laser, scanAt(p), params.max_range, params.max_urange);
    }
    return map;
  }
};

double trace(const Covariance& c) { return c.m[0][0] + c.m[1][1] + c.m[2][2]; }
}  // namespace

TEST(PoseFusion, NoInformationLeavesThePrediction) {
  const Covariance prior = Covariance::diagonal(0.01, 0.02, 0.003);
  Covariance post;
  const Pose2 fused = fuse(Pose2(1, 2, 0.3), prior, Pose2(1.5, 1.0, -0.2), Information(), &post);
  EXPECT_DOUBLE_EQ(fused.x, 1.0);
  EXPECT_DOUBLE_EQ(fused.y, 2.0);
  EXPECT_DOUBLE_EQ(fused.theta, 0.3);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(post.m[i][j], prior.m[i][j], 1e-15);
}

TEST(PoseFusion, WeighsPredictionAndMeasurementByTheirInformation) {
  // Equal variances: half way; a prediction known exactly: the prediction.
  Covariance post;
  Pose2 fused = fuse(Pose2(0, 0, 0), Covariance::diagonal(0.01, 0.01, 0.01), Pose2(0.2, -0.1, 0.1),
                     Information::diagonal(100, 100, 100), &post);
  EXPECT_NEAR(fused.x, 0.1, 1e-12);
  EXPECT_NEAR(fused.y, -0.05, 1e-12);
  EXPECT_NEAR(fused.theta, 0.05, 1e-12);
  EXPECT_NEAR(post.m[0][0], 0.005, 1e-12);
  fused = fuse(Pose2(0, 0, 0), Covariance(), Pose2(0.2, -0.1, 0.1),
               Information::diagonal(100, 100, 100), &post);
  EXPECT_NEAR(fused.x, 0.0, 1e-15);
  EXPECT_NEAR(trace(post), 0.0, 1e-15);
}

TEST(PoseFusion, PropagationGrowsByTheIncrementAndTheHeadingsLever) {
  // A heading known to 0.1 rad, then 2 m straight ahead along +x: the position gains
  // (2 x 0.1)^2 across the motion on top of the increment's own variance.
  const Covariance c = propagate(Covariance::diagonal(0, 0, 0.01), Pose2(0, 0, 0), Pose2(2, 0, 0),
                                 1e-4, 4e-4);
  EXPECT_NEAR(c.m[0][0], 1e-4, 1e-12);
  EXPECT_NEAR(c.m[1][1], 0.04 + 1e-4, 1e-12);
  EXPECT_NEAR(c.m[1][2], 0.02, 1e-12);
  EXPECT_NEAR(c.m[2][2], 0.01 + 4e-4, 1e-12);
}

TEST(PoseFusion, ACornerCorrectsADriftedPrediction) {
  // Two walls meeting ahead of the robot pin x, y and the heading: a particle that drifted
  // (a wide carried covariance) takes the match, and its covariance shrinks to the scan's.
  Scene s{SyntheticWorld(10.0, 10.0, 0.01)};
  s.world.fillRect(6.0, 0.0, 6.2, 10.0);
  s.world.fillRect(0.0, 7.0, 10.0, 7.2);
  const Pose2 truth(3.5, 4.5, 0.6);
  s.scanAt(truth);
  const GridMap map = s.mapAround(truth);
  ScanMatcher matcher(s.params);
  const ScanPoints points = matcher.matchPoints(s.laser, s.scanAt(truth));
  const Pose2 predicted(truth.x + 0.10, truth.y - 0.08, truth.theta + 0.04);
  const Covariance prior = Covariance::diagonal(0.15 * 0.15, 0.15 * 0.15, 0.08 * 0.08);
  Pose2 match;
  matcher.match(map, predicted, points, &match, {0.15, 0.08});
  const Information info = matcher.calibratedInformation(match, points);
  Covariance post;
  const Pose2 fused = fuse(predicted, prior, match, info, &post);
  EXPECT_NEAR(fused.x, truth.x, 0.02);
  EXPECT_NEAR(fused.y, truth.y, 0.02);
  EXPECT_NEAR(fused.theta, truth.theta, 0.01);
  // Sixty-odd cells of wall at lsigma each: about 2-3 cm and a degree, from 15 cm and 5 degrees.
  EXPECT_LT(post.m[0][0], 0.05 * prior.m[0][0]);
  EXPECT_LT(post.m[1][1], 0.05 * prior.m[1][1]);
  EXPECT_LT(post.m[2][2], 0.05 * prior.m[2][2]);
}

TEST(PoseFusion, ALoneWallCorrectsAcrossItOnly) {
  // One straight wall ahead: the scan says how far the wall is and how it is turned, nothing
  // of where along it the robot stands. The fused pose keeps the prediction's offset along
  // the wall and takes the match across it.
  Scene s{SyntheticWorld(20.0, 10.0, 0.01)};
  s.world.fillRect(0.0, 7.0, 20.0, 7.2);
  const Pose2 truth(10.0, 4.0, M_PI / 2);
  s.scanAt(truth);
  const GridMap map = s.mapAround(truth);
  ScanMatcher matcher(s.params);
  const ScanPoints points = matcher.matchPoints(s.laser, s.scanAt(truth));
  const Pose2 predicted(truth.x + 0.06, truth.y - 0.06, truth.theta);
  const Covariance prior = Covariance::diagonal(0.05 * 0.05, 0.05 * 0.05, 0.02 * 0.02);
  Pose2 match;
  matcher.match(map, predicted, points, &match, {0.05, 0.02});
  const Information info = matcher.calibratedInformation(match, points);
  Covariance post;
  const Pose2 fused = fuse(predicted, prior, match, info, &post);
  EXPECT_NEAR(fused.y, truth.y, 0.015);          // across the wall: corrected
  EXPECT_NEAR(fused.x, predicted.x, 0.015);      // along it: the prediction's
  EXPECT_GT(post.m[0][0], 0.5 * prior.m[0][0]);  // and still as uncertain there
  EXPECT_LT(post.m[1][1], 0.1 * prior.m[1][1]);
}

TEST(PoseFusion, AScanOfOpenFloorLeavesThePredictionAndTheCovarianceGrows) {
  // Nothing within range: the match has no information; every update adds the increment's
  // spread to the carried covariance.
  Scene s{SyntheticWorld(40.0, 40.0, 0.05)};
  ScanMatcher matcher(s.params);
  const Ranges ranges = s.scanAt(Pose2(20.0, 20.0, 0.0));
  const ScanPoints points = matcher.matchPoints(s.laser, ranges);
  EXPECT_TRUE(points.points.empty());
  Covariance cov;
  Pose2 pose(20.0, 20.0, 0.0);
  double last = 0.0;
  for (int k = 0; k < 5; ++k) {
    const Pose2 inc(0.5, 0.0, 0.1);
    const Covariance predicted_cov = propagate(cov, pose, inc, 2.5e-5, 1e-4);
    const Pose2 predicted = pose * inc;
    pose = fuse(predicted, predicted_cov, Pose2(predicted.x + 0.3, predicted.y, predicted.theta),
                matcher.calibratedInformation(predicted, points), &cov);
    EXPECT_DOUBLE_EQ(pose.x, predicted.x);
    EXPECT_GT(trace(cov), last);
    last = trace(cov);
  }
}

namespace {
// A straight run with exact odometry (scale 1) and a map drawn at the particle's own poses: each
// match registers the scan against the map of the previous pose, so it is that pose moved by
// the true step, shortened by `pull` times the step times the share of end points in unmapped
// space (0 or 0.5, by turns), and otherwise exact to `sd`. Returns the estimated calibration and
// pulls.
OdometryScale learnOnBiasedMatches(bool model_pulls, double pull) {
  const double sd = 0.01, srr = 0.01, stt = 0.02;
  Covariance cov = Covariance::diagonal(0, 0, 0, srr * srr, stt * stt, model_pulls ? 1.0 : 0.0,
                                        model_pulls ? 0.03 : 0.0);
  OdometryScale scale;
  Information info;
  for (int i = 0; i < 3; ++i) info.m[i][i] = 1.0 / (sd * sd);
  Pose2 estimate(0, 0, 0);
  const Pose2 inc(0.5, 0.0, 0.0);
  for (int k = 0; k < 400; ++k) {
    const Pose2 predicted = predict(estimate, inc, scale);
    const Covariance prior = propagate(cov, estimate, inc, 2.5e-5, 1e-4, scale);
    MatchBiasRegressors r;
    r.ux = 1.0;
    r.unknown_step = 0.5 * (k % 2 ? 0.5 : 0.0);
    const Pose2 registered = estimate * inc;
    const Pose2 measured(registered.x + pull * r.unknown_step, registered.y, registered.theta);
    estimate = fuse(predicted, prior, measured, info, &cov, &scale, nullptr,
                    model_pulls ? &r : nullptr);
  }
  return scale;
}
}  // namespace

TEST(PoseFusion, TheMatchesPullIsNotTakenForOdometrysScale) {
  // Matches 10 % short where half the end points are unmapped: without the pull in the state,
  // the distance scale absorbs it (short by a few percent); with it, the scale stays at 1 and
  // the pull is learnt.
  const OdometryScale without = learnOnBiasedMatches(false, -0.1);
  EXPECT_LT(without.distance, 0.985);
  const OdometryScale with = learnOnBiasedMatches(true, -0.1);
  EXPECT_NEAR(with.distance, 1.0, 0.003);
  EXPECT_NEAR(with.unknown_pull, -0.1, 0.02);
}
