#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "gmapping_lite/scan_matcher.h"
#include "synthetic.h"

using namespace gmapping_lite;  // NOLINT: test file

namespace {
unsigned visits(const GridMap& map, int i, int j) {
  const Cell* c = map.find(i, j);
  return c ? c->visits : 0u;
}

struct Fixture {
  SyntheticWorld world = SyntheticWorld::office();
  RunOptions options;
  LaserGeometry laser;

  Ranges scanAt(const Pose2& pose) {
    std::vector<Pose2> still{pose};
    SyntheticRun run = simulateRun(world, still, options);
    laser = run.laser;
    return run.steps.front().ranges;
  }
};
}  // namespace

TEST(ScanMatcher, RecoversAPerturbedPose) {
  Fixture f;
  MatcherParams params;
  GridMap map(0.05);
  // Build a map from scans taken around one spot, as the filter would.
  const Pose2 truth(3.0, 5.0, 0.2);
  for (double a = -1.2; a <= 1.2; a += 0.3) {
    const Pose2 p(truth.x, truth.y, truth.theta + a);
    const Ranges r = f.scanAt(p);
    registerScan(&map, p, f.laser, r, params.max_range, params.max_urange);
  }
  ScanMatcher matcher(params);
  const Ranges ranges = f.scanAt(truth);
  const ScanPoints points = matcher.matchPoints(f.laser, ranges);
  ASSERT_GT(points.points.size(), 500u);
  const Pose2 guess(truth.x + 0.08, truth.y - 0.06, truth.theta + 0.04);
  Pose2 best;
  const double score = matcher.match(map, guess, points, &best);
  EXPECT_GT(score, 0.8 * points.points.size());
  EXPECT_NEAR(best.x, truth.x, 0.02);
  EXPECT_NEAR(best.y, truth.y, 0.02);
  EXPECT_NEAR(best.theta, truth.theta, 0.01);
  // The likelihood is higher at the match than at the guess.
  EXPECT_GT(matcher.likelihood(best, points, nullptr), matcher.likelihood(guess, points, nullptr));
}

TEST(ScanMatcher, LskipThinsTheBeams) {
  Fixture f;
  MatcherParams params;
  params.lskip = 9;
  ScanMatcher matcher(params);
  const Ranges ranges = f.scanAt(Pose2(3.0, 5.0, 0.0));
  const ScanPoints points = matcher.matchPoints(f.laser, ranges);
  EXPECT_LE(points.points.size(), 64u);
  EXPECT_GE(points.points.size(), 50u);
}

TEST(RegisterScan, InfClearsToMaxUrangeNanAndInvalidSkipped) {
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  LaserGeometry laser = LaserGeometry::planar(Pose2(), -M_PI / 2, M_PI / 2, 3);  // -y, +x, +y
  GridMap map(0.1);
  registerScan(&map, Pose2(0.05, 0.05, 0.0), laser, Ranges{inf, nan, 2.0f}, 8.0, 3.0);
  // +inf along -y: free all the way to maxUrange (3 m), no hit.
  for (int j = -1; j >= -29; --j) {
    ASSERT_NE(map.find(0, j), nullptr) << j;
    EXPECT_EQ(map.find(0, j)->hits, 0u);
  }
  EXPECT_EQ(visits(map, 0, -30), 1u);
  EXPECT_EQ(visits(map, 0, -31), 0u);
  // NaN along +x: nothing.
  EXPECT_EQ(visits(map, 5, 0), 0u);
  // 2 m along +y: free then a hit.
  EXPECT_EQ(map.find(0, 20)->hits, 1u);
  EXPECT_EQ(map.find(0, 10)->hits, 0u);
}

TEST(RegisterScan, BeyondMaxUrangeClearsWithoutHitBeyondMaxRangeIgnored) {
  LaserGeometry laser = LaserGeometry::planar(Pose2(), 0.0, M_PI / 2, 2);  // +x, +y
  GridMap map(0.1);
  registerScan(&map, Pose2(0.05, 0.05, 0.0), laser, Ranges{5.0f, 9.0f}, 8.0, 3.0);
  EXPECT_EQ(map.find(29, 0)->hits, 0u);
  EXPECT_EQ(map.find(30, 0)->hits, 0u);
  EXPECT_EQ(visits(map, 31, 0), 0u);
  EXPECT_EQ(visits(map, 0, 5), 0u);
}

TEST(RegisterScan, InfClearsNoFurtherThanMaxRange) {
  // gmapping's documented default maxUrange is 80 m; an 8 m sensor's missing return must not
  // clear 80 m of floor.
  const float inf = std::numeric_limits<float>::infinity();
  LaserGeometry laser = LaserGeometry::planar(Pose2(), 0.0, 0.1, 1);  // +x
  GridMap map(0.1);
  registerScan(&map, Pose2(0.05, 0.05, 0.0), laser, Ranges{inf}, 2.0, 80.0);
  EXPECT_EQ(visits(map, 19, 0), 1u);
  EXPECT_EQ(visits(map, 21, 0), 0u);
}

TEST(ScanMatcher, MarginTellsOnePeakFromTwo) {
  // A grid of poses along x, one step apart; the scan's information pins x to 1 cm.
  const Information info = Information::diagonal(1e4, 1e4, 1e4);
  std::vector<ScanMatcher::Candidate> grid;
  for (int i = -10; i <= 10; ++i) grid.push_back({Pose2(0.1 * i, 0.0, 0.0), -std::abs(i) * 0.5});
  // One peak at 0: the best rival (beyond one step and 3 sigma) is 1.0 lower.
  EXPECT_NEAR(ScanMatcher::margin(grid, grid[10], info, 0.1, 0.1), 1.0, 1e-9);
  // A second place as good as the best, far off: no margin.
  grid[20].value = 0.0;
  EXPECT_NEAR(ScanMatcher::margin(grid, grid[10], info, 0.1, 0.1), 0.0, 1e-9);
  // Nothing outside the match's own uncertainty (a corridor): no rival at all.
  const Information weak = Information::diagonal(1.0, 1.0, 1.0);
  EXPECT_TRUE(std::isinf(ScanMatcher::margin(grid, grid[10], weak, 0.1, 0.1)));
}

// Disabled: the property this asks for is not met yet. Point-to-point matching still slides
// 6-19 mm per scan along a lone wall (the same slide derails warehouse starts; issue 16).
TEST(ScanMatcher, DISABLED_TurningInFrontOfAWallDoesNotSlideAlongIt) {
  // A corridor wall and nothing else in reach: the scan fixes y and the heading, never x. The
  // robot turns on the spot, each scan reaching past what the map holds of the wall; the
  // match must not drag the pose along the wall towards the mapped part.
  Fixture f;
  f.world = SyntheticWorld(20.0, 10.0, 0.01);
  f.world.fillRect(0.0, 6.0, 20.0, 6.2);
  MatcherParams params;
  params.max_range = params.max_urange = 6.0;
  ScanMatcher matcher(params);
  GridMap map(0.05);
  Pose2 pose(10.0, 5.0, M_PI / 2 - 0.5);
  registerScan(&map, pose, f.laser, f.scanAt(pose), params.max_range, params.max_urange);
  const OdometryPrior prior{0.08, 0.03};
  for (int step = 0; step < 4; ++step) {
    const Pose2 truth(10.0, 5.0, pose.theta + 0.25);
    const Ranges ranges = f.scanAt(truth);
    Pose2 best;
    matcher.match(map, Pose2(pose.x, pose.y, truth.theta), matcher.matchPoints(f.laser, ranges),
                  &best, prior);
    // Point-to-point matching slid 6-19 mm here; point-to-line stays within 3 mm.
    EXPECT_NEAR(best.x, truth.x, 0.008) << "step " << step;
    EXPECT_NEAR(best.y, truth.y, 0.01) << "step " << step;
    EXPECT_NEAR(best.theta, truth.theta, 0.005) << "step " << step;
    pose = best;
    registerScan(&map, pose, f.laser, ranges, params.max_range, params.max_urange);
  }
}

TEST(ScanMatcher, KnownPointsAreKnownWhereverTheClimbReaches) {
  // A corridor along x, mapped from one pose with a short usable range, then scanned from
  // further along with the full range: the scan's end points on the walls run past the mapped
  // part. knownPoints keeps a point only if its end point is in seen space at the pose and at
  // the pose moved by +-reach along x and along y, so a climb within that reach cannot carry a
  // kept point into unknown space (where it would score differently).
  Fixture f;
  f.world = SyntheticWorld(20.0, 10.0, 0.01);
  f.world.fillRect(0.0, 3.9, 20.0, 4.0);
  f.world.fillRect(0.0, 6.0, 20.0, 6.1);
  MatcherParams params;
  ScanMatcher matcher(params);
  GridMap map(0.05);
  const Pose2 first(2.0, 5.0, 0.0);
  registerScan(&map, first, f.laser, f.scanAt(first), 8.0, 4.0);
  const Pose2 pose(2.4, 5.0, 0.0);
  const ScanPoints all = matcher.matchPoints(f.laser, f.scanAt(pose));
  matcher.prepare(map, pose, all);
  auto known = [&](const Pose2& at, const ScanPoints& points) {
    int matched = 0, contradicting = 0;
    matcher.agreement(at, points, &matched, &contradicting);
    return matched + contradicting;
  };
  // Reach 0: the points known at the pose itself.
  const ScanPoints here = matcher.knownPoints(pose, all, 0.0);
  EXPECT_EQ(known(pose, here), static_cast<int>(here.points.size()));
  EXPECT_EQ(known(pose, all), static_cast<int>(here.points.size()));
  EXPECT_LT(here.points.size(), all.points.size());  // the walls run past the map
  // With a reach, a subset, known at every displaced pose.
  const double r = 0.05;
  const ScanPoints kept = matcher.knownPoints(pose, all, r);
  EXPECT_LT(kept.points.size(), here.points.size());  // the points near the map's edge go
  EXPECT_GT(kept.points.size(), here.points.size() / 2);
  double beams = 0.0;
  for (const auto& p : kept.points) beams += p.beams;
  EXPECT_DOUBLE_EQ(kept.beams, beams);
  const Pose2 moved[4] = {{pose.x + r, pose.y, pose.theta}, {pose.x - r, pose.y, pose.theta},
                          {pose.x, pose.y + r, pose.theta}, {pose.x, pose.y - r, pose.theta}};
  for (const Pose2& m : moved) EXPECT_EQ(known(m, kept), static_cast<int>(kept.points.size()));
  // Some of the points known at the pose fall into unknown space one reach forward: those the
  // reach leaves out, which would otherwise hold a climb back from moving forward.
  EXPECT_LT(known(moved[0], here), static_cast<int>(here.points.size()));
}
