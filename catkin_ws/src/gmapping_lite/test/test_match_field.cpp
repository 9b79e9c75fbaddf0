#include <gtest/gtest.h>

#include <cmath>

#include "gmapping_lite/match_field.h"

using gmapping_lite::CellIndex;
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
  field.build(map, {-20, -20}, {60, 60}, 0.1, 0.5);
  // On the wall's line but 0.3 m past its mapped end: on the wall.
  EXPECT_NEAR(field.distance2(1.3, 1.0), 0.0, 1e-4);
  EXPECT_NEAR(field.distance2(-0.3, 1.0), 0.0, 1e-4);
  // 0.1 m in front of the wall, anywhere along it.
  EXPECT_NEAR(std::sqrt(field.distance2(0.5, 0.9)), 0.1, 0.005);
  EXPECT_NEAR(std::sqrt(field.distance2(0.02, 0.9)), 0.1, 0.005);
  // Beyond the radius or outside the field: capped.
  EXPECT_DOUBLE_EQ(field.distance2(0.5, 0.2), 0.25);
  EXPECT_DOUBLE_EQ(field.distance2(50.0, 1.0), 0.25);
}

TEST(MatchField, IsolatedCellsMeasurePointToPoint) {
  GridMap map(0.05);
  map.traceBeam(0.0, 0.0, 1.02, 1.02, true);  // one lone hit: a thin post
  MatchField field;
  field.build(map, {-20, -20}, {60, 60}, 0.1, 0.5);
  EXPECT_NEAR(std::sqrt(field.distance2(1.22, 1.02)), 0.2, 0.005);
  EXPECT_NEAR(std::sqrt(field.distance2(1.02, 0.82)), 0.2, 0.005);
}
