#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "gmapping_lite/match_field.h"

using gmapping_lite::GridMap;
using gmapping_lite::MatchField;

namespace {
// A wall along y = 1.0 from x = 0 to x = 1 (hits just below the line), seen from below.
GridMap wallMap() {
  GridMap map(0.05);
  for (double x = 0.01; x < 1.0; x += 0.01) map.traceBeam(x, 0.0, x, 0.999, true);
  return map;
}
}  // namespace

TEST(MatchField, WallCellsMeasureAcrossTheWallOnly) {
  const GridMap map = wallMap();
  MatchField field;
  field.build(map, {{0.0, 1.0}, {0.5, 1.0}, {1.0, 1.0}}, 0.4, 0.1, 0.5);
  // On the wall's line but 0.3 m past its mapped end: on the wall.
  EXPECT_NEAR(field.distance2(1.3, 1.0), 0.0, 1e-4);
  EXPECT_NEAR(field.distance2(-0.3, 1.0), 0.0, 1e-4);
  // 0.1 m in front of the wall, anywhere along it.
  EXPECT_NEAR(std::sqrt(field.distance2(0.5, 0.9)), 0.1, 0.005);
  EXPECT_NEAR(std::sqrt(field.distance2(0.02, 0.9)), 0.1, 0.005);
  // Beyond the radius, or further from the focus than it was built for: capped.
  EXPECT_DOUBLE_EQ(field.distance2(0.5, 0.2), 0.25);
  EXPECT_DOUBLE_EQ(field.distance2(50.0, 1.0), 0.25);
}

TEST(MatchField, IsolatedCellsMeasurePointToPoint) {
  GridMap map(0.05);
  map.traceBeam(0.0, 0.0, 1.02, 1.02, true);  // one lone hit: a thin post
  MatchField field;
  field.build(map, {{1.0, 1.0}}, 0.4, 0.1, 0.5);
  EXPECT_NEAR(std::sqrt(field.distance2(1.22, 1.02)), 0.2, 0.005);
  EXPECT_NEAR(std::sqrt(field.distance2(1.02, 0.82)), 0.2, 0.005);
}

TEST(MatchField, OnlyTheFocusIsComputed) {
  GridMap map(0.05);
  for (double x = 0.01; x < 10.0; x += 0.01) map.traceBeam(x, 0.0, x, 0.999, true);
  MatchField near_start, everywhere;
  near_start.build(map, {{0.5, 1.0}}, 0.3, 0.1, 0.5);
  std::vector<MatchField::Point> along_the_wall;
  for (double x = 0.5; x < 10.0; x += 0.5) along_the_wall.push_back({x, 1.0});
  everywhere.build(map, along_the_wall, 0.3, 0.1, 0.5);
  EXPECT_LT(near_start.seedCount(), everywhere.seedCount() / 3);
  // Where both are computed, they agree.
  EXPECT_DOUBLE_EQ(near_start.distance2(0.6, 0.8), everywhere.distance2(0.6, 0.8));
  EXPECT_NEAR(std::sqrt(everywhere.distance2(9.4, 0.8)), 0.2, 0.005);
  EXPECT_DOUBLE_EQ(near_start.distance2(9.4, 0.8), 0.25);
}
