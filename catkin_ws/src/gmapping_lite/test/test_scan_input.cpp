#include <gtest/gtest.h>

#include <cmath>
#include <limits>

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
