#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include <tf2/LinearMath/Quaternion.h>

#include "gmapping_lite/param_table.h"
#include "gmapping_lite/scan_input.h"

using namespace gmapping_lite;  // NOLINT: test file

namespace {
tf2::Transform mount(double roll, double pitch, double yaw, double x = 0.1, double y = 0.0) {
  tf2::Quaternion q;
  q.setRPY(roll, pitch, yaw);
  return tf2::Transform(q, tf2::Vector3(x, y, 0.3));
}
}  // namespace

TEST(ScanInput, PlanarLaserKeepsItsAngles) {
  LaserGeometry g;
  std::string error;
  ASSERT_TRUE(makeLaserGeometry(mount(0, 0, 0), -0.5, 0.25, 5, 0.1, &g, &error)) << error;
  EXPECT_NEAR(g.origin.x, 0.1, 1e-12);
  EXPECT_NEAR(g.beams.front().angle, -0.5, 1e-12);
  EXPECT_NEAR(g.beams.back().angle, 0.5, 1e-12);
  EXPECT_NEAR(g.beams[2].scale, 1.0, 1e-12);
}

TEST(ScanInput, AsymmetricScanAndYawedMount) {
  LaserGeometry g;
  std::string error;
  ASSERT_TRUE(makeLaserGeometry(mount(0, 0, M_PI / 2), -0.2, 0.1, 10, 0.1, &g, &error));
  EXPECT_NEAR(g.beams.front().angle, M_PI / 2 - 0.2, 1e-12);
  EXPECT_NEAR(g.beams.back().angle, M_PI / 2 + 0.7, 1e-12);
}

TEST(ScanInput, UpsideDownLaserMirrorsTheBeams) {
  LaserGeometry g;
  std::string error;
  const tf2::Transform flipped = mount(M_PI, 0, 0);
  EXPECT_TRUE(upsideDown(flipped));
  EXPECT_FALSE(upsideDown(mount(0, 0, 0)));
  ASSERT_TRUE(makeLaserGeometry(flipped, -0.5, 0.25, 5, 0.1, &g, &error)) << error;
  // Beam 0 points at -0.5 rad in the laser frame, which is +0.5 rad in the base frame.
  EXPECT_NEAR(g.beams.front().angle, 0.5, 1e-9);
  EXPECT_NEAR(g.beams.back().angle, -0.5, 1e-9);
}

TEST(ScanInput, SmallTiltIsProjectedLargeTiltIsRefused) {
  LaserGeometry g;
  std::string error;
  ASSERT_TRUE(makeLaserGeometry(mount(0, 0.05, 0), 0.0, 0.1, 1, 0.1, &g, &error)) << error;
  EXPECT_NEAR(g.beams[0].scale, std::cos(0.05), 1e-9);  // the forward beam dips
  EXPECT_FALSE(makeLaserGeometry(mount(0, 0.3, 0), 0.0, 0.1, 1, 0.1, &g, &error));
  EXPECT_NE(error.find("tilted"), std::string::npos);
}

TEST(ScanInput, RangesFollowRep117) {
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const Ranges r = toRanges({nan, 0.2f, -inf, 1.5f, 8.0f, 9.0f, inf}, 0.45, 8.0);
  EXPECT_TRUE(std::isnan(r[0]));
  EXPECT_TRUE(std::isnan(r[1]));  // below range_min
  EXPECT_TRUE(std::isnan(r[2]));
  EXPECT_FLOAT_EQ(r[3], 1.5f);
  EXPECT_TRUE(std::isinf(r[4]) && r[4] > 0);  // at range_max: no return
  EXPECT_TRUE(std::isinf(r[5]) && r[5] > 0);
  EXPECT_TRUE(std::isinf(r[6]) && r[6] > 0);
}

namespace {
// A consistent scan: the synthetic robot's 360 beams over -2..2 rad, ranges 0.1..8 m.
struct Layout {
  double angle_min = -2.0, angle_max = 2.0, angle_increment = 4.0 / 359;
  std::size_t count = 360;
  double range_min = 0.1, range_max = 8.0;
};
std::optional<std::string> problem(const Layout& l) {
  return scanProblem(l.angle_min, l.angle_max, l.angle_increment, l.count, l.range_min,
                     l.range_max);
}
// The reason given for `l`, "" when it is accepted.
std::string reason(const Layout& l) { return problem(l).value_or(""); }
bool mentions(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}
}  // namespace

TEST(ScanProblem, ConsistentScansPass) {
  EXPECT_EQ(reason(Layout{}), "");
  // A full turn as drivers publish it, in float32: -pi..pi with 360 or 361 beams.
  const double pi = static_cast<float>(M_PI), inc = static_cast<float>(2 * M_PI / 360);
  EXPECT_EQ(reason({-pi, pi, inc, 361, 0.1, 8.0}), "");
  EXPECT_EQ(reason({-pi, pi, inc, 360, 0.1, 8.0}), "");
  EXPECT_EQ(reason({0.0, 2 * M_PI - inc, inc, 360, 0.1, 8.0}), "");
  // Clockwise lasers count down; a single beam has angle_min == angle_max.
  EXPECT_EQ(reason({2.0, -2.0, -4.0 / 359, 360, 0.1, 8.0}), "");
  EXPECT_EQ(reason({0.3, 0.3, 0.01, 1, 0.0, 8.0}), "");
  // Rounding: one beam more or fewer than the angles give is accepted.
  Layout l;
  l.count = 361;
  EXPECT_EQ(reason(l), "");
  l.count = 359;
  EXPECT_EQ(reason(l), "");
  // A huge range_max is the defaults' business (rangeDefaults), not a malformed scan.
  l.range_max = 1e30;
  EXPECT_EQ(reason(l), "");
}

TEST(ScanProblem, BadAngleIncrementIsNamed) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (double inc : {0.0, -0.0, nan, inf, -inf}) {
    Layout l;
    l.angle_increment = inc;
    const std::string r = reason(l);
    EXPECT_TRUE(mentions(r, "angle_increment is ") && mentions(r, "non-zero")) << inc << ": " << r;
  }
}

TEST(ScanProblem, RangeCountMustMatchTheAngles) {
  Layout l;
  l.count = 180;  // half the beams the angles promise
  std::string r = reason(l);
  EXPECT_TRUE(mentions(r, "180 ranges") && mentions(r, "make 360 beams")) << r;
  l.count = 358;  // two short: beyond rounding
  EXPECT_TRUE(mentions(reason(l), "358 ranges")) << reason(l);
  l.count = 362;
  EXPECT_TRUE(mentions(reason(l), "362 ranges")) << reason(l);
  l.count = 0;
  EXPECT_EQ(reason(l), "the scan has no ranges");
  // The increment points away from angle_max: no beam count fits.
  l = Layout{};
  l.angle_increment = -l.angle_increment;
  r = reason(l);
  EXPECT_TRUE(mentions(r, "opposite sign")) << r;
  // A tiny increment promises more beams than any message holds, without overflow.
  l = Layout{};
  l.angle_increment = 1e-300;
  EXPECT_TRUE(mentions(reason(l), "360 ranges")) << reason(l);
}

TEST(ScanProblem, MoreThanOneTurnIsRefused) {
  // 720 beams over two turns: consistent counts, but beams overlap themselves.
  const double inc = 4 * M_PI / 719;
  std::string r = reason({-2 * M_PI, 2 * M_PI, inc, 720, 0.1, 8.0});
  EXPECT_TRUE(mentions(r, "more than one full turn")) << r;
  r = reason({2 * M_PI, -2 * M_PI, -inc, 720, 0.1, 8.0});
  EXPECT_TRUE(mentions(r, "more than one full turn")) << r;
  // Just past one turn (by a beam of a 1000-beam laser) is also more than one turn.
  r = reason({0.0, 2 * M_PI + 0.00628, 0.00628, 1002, 0.1, 8.0});
  EXPECT_TRUE(mentions(r, "more than one full turn")) << r;
}

TEST(ScanProblem, RangeLimitsMustBeFiniteAndOrdered) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  Layout l;
  for (double v : {nan, inf, -inf, -0.5}) {
    l = Layout{};
    l.range_min = v;
    EXPECT_TRUE(mentions(reason(l), "range_min is ")) << v << ": " << reason(l);
    l = Layout{};
    l.range_max = v;
    EXPECT_TRUE(mentions(reason(l), "range_max is ")) << v << ": " << reason(l);
  }
  l = Layout{};
  l.range_max = 0.0;
  EXPECT_TRUE(mentions(reason(l), "range_max is 0")) << reason(l);
  l = Layout{};
  l.range_min = 8.0;
  l.range_max = 0.1;
  EXPECT_EQ(reason(l), "range_min 8 is not below range_max 0.1");
  l.range_min = l.range_max = 5.0;
  EXPECT_EQ(reason(l), "range_min 5 is not below range_max 5");
}

TEST(ScanProblem, AngleLimitsMustBeFinite) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (double v : {nan, inf, -inf}) {
    Layout l;
    l.angle_min = v;
    EXPECT_TRUE(mentions(reason(l), "angle_min is ")) << v << ": " << reason(l);
    l = Layout{};
    l.angle_max = v;
    EXPECT_TRUE(mentions(reason(l), "angle_max is ")) << v << ": " << reason(l);
  }
}

TEST(ScanDrops, FirstAtOnceThenThrottledWithTheCount) {
  ScanDrops drops(5.0);
  EXPECT_TRUE(drops.count(100.0));  // the first at once
  EXPECT_FALSE(drops.count(100.1));
  EXPECT_FALSE(drops.count(104.9));
  EXPECT_TRUE(drops.count(105.0));  // the period has passed
  EXPECT_FALSE(drops.count(106.0));
  EXPECT_FALSE(drops.count(104.0));  // stamps a little out of order: still throttled
  EXPECT_EQ(drops.total(), 6);
  EXPECT_TRUE(drops.count(1.0));  // a bag played again: warn again at once
  EXPECT_FALSE(drops.count(2.0));
  EXPECT_EQ(drops.total(), 8);
}

TEST(ParamTable, HugeRangeMaxIsClampedForTheDefaults) {
  const double inf = std::numeric_limits<double>::infinity();
  for (double range_max : {1e4, 1e30, inf}) {
    SlamParams p;
    const std::string note = rangeDefaults(&p, range_max, false, false);
    EXPECT_NEAR(p.matcher.max_range, kMaxDefaultRange - 0.01, 1e-12) << range_max;
    EXPECT_EQ(p.matcher.max_urange, p.matcher.max_range);
    EXPECT_TRUE(mentions(note, "range_max") && mentions(note, "using maxRange 80 m")) << note;
  }
  SlamParams p;
  EXPECT_EQ(rangeDefaults(&p, 30.0, false, false), "");  // a Hokuyo's 30 m is kept
  EXPECT_NEAR(p.matcher.max_range, 29.99, 1e-12);
  // Explicit settings are the user's: no clamp, no note.
  p.matcher.max_range = 200.0;
  p.matcher.max_urange = 50.0;
  EXPECT_EQ(rangeDefaults(&p, 1e30, true, true), "");
  EXPECT_EQ(p.matcher.max_range, 200.0);
  EXPECT_EQ(p.matcher.max_urange, 50.0);
  // maxUrange alone set: maxRange still comes from the clamped range_max.
  p.matcher.max_urange = 6.0;
  EXPECT_NE(rangeDefaults(&p, 1e30, false, true), "");
  EXPECT_NEAR(p.matcher.max_range, kMaxDefaultRange - 0.01, 1e-12);
  EXPECT_EQ(p.matcher.max_urange, 6.0);
  // A laser reaching a few centimetres keeps a positive maxRange.
  EXPECT_EQ(rangeDefaults(&p, 0.015, false, false), "");
  EXPECT_GT(p.matcher.max_range, 0.0);
}

TEST(ParamTable, NamesAndDefaultsAreGmappings) {
  const SlamParams p;
  auto get = [&](const std::string& name) {
    for (const auto& e : paramTable())
      if (e.name == name) return e.get(p);
    ADD_FAILURE() << "missing " << name;
    return 0.0;
  };
  EXPECT_EQ(get("particles"), 30);
  EXPECT_EQ(get("linearUpdate"), 1.0);
  EXPECT_EQ(get("angularUpdate"), 0.5);
  EXPECT_EQ(get("temporalUpdate"), -1.0);
  EXPECT_EQ(get("resampleThreshold"), 0.5);
  EXPECT_EQ(get("minimumScore"), 0.0);
  EXPECT_EQ(get("sigma"), 0.05);
  EXPECT_EQ(get("kernelSize"), 1);
  EXPECT_EQ(get("lstep"), 0.05);
  EXPECT_EQ(get("astep"), 0.05);
  EXPECT_EQ(get("iterations"), 5);
  EXPECT_EQ(get("lsigma"), 0.075);
  EXPECT_EQ(get("ogain"), 3.0);
  EXPECT_EQ(get("lskip"), 0);
  EXPECT_EQ(get("srr"), 0.1);
  EXPECT_EQ(get("srt"), 0.2);
  EXPECT_EQ(get("str"), 0.1);
  EXPECT_EQ(get("stt"), 0.2);
  EXPECT_EQ(get("xmin"), -100);
  EXPECT_EQ(get("ymax"), 100);
  EXPECT_EQ(get("delta"), 0.05);
  EXPECT_EQ(get("occ_thresh"), 0.25);
  SlamParams q;
  EXPECT_TRUE(setParam(&q, "lskip", 10));
  EXPECT_EQ(q.matcher.lskip, 10);
  EXPECT_FALSE(setParam(&q, "noSuchParam", 1));
  rangeDefaults(&q, 8.0, false, false);
  EXPECT_NEAR(q.matcher.max_range, 7.99, 1e-12);
  EXPECT_NEAR(q.matcher.max_urange, 7.99, 1e-12);
}

TEST(ParamTable, ValuesAreCheckedBeforeAnIntegerFieldCutsThem) {
  // 2.5 particles would be stored as 2, a seed of -1 or 1e300 is undefined as an unsigned.
  EXPECT_NE(valueProblem("particles", 2.5).find("particles is 2.5: it must be a whole number"), std::string::npos);
  EXPECT_NE(valueProblem("lskip", 0.5).find("whole number"), std::string::npos);
  EXPECT_NE(valueProblem("seed", -1).find("seed is -1"), std::string::npos);
  EXPECT_NE(valueProblem("seed", 1e300).find("seed is 1e+300"), std::string::npos);
  EXPECT_NE(valueProblem("loop_closure", 5).find("0 or 1"), std::string::npos);
  EXPECT_NE(valueProblem("delta", std::nan("")).find("delta is nan"), std::string::npos);
  EXPECT_EQ(valueProblem("particles", 30), "");
  EXPECT_EQ(valueProblem("seed", 4294967295.0), "");
  EXPECT_EQ(valueProblem("loop_closure", 1), "");
  EXPECT_EQ(valueProblem("noSuchParam", 1), "");
}
