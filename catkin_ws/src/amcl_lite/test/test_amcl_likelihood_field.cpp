#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "amcl_lite/likelihood_field.h"

using amcl_lite::GridMap;
using amcl_lite::LikelihoodField;

namespace {
GridMap emptyMap(int w, int h) {
  GridMap m;
  m.resolution = 0.1;
  m.width = w;
  m.height = h;
  m.cells.assign(w * h, 0);
  return m;
}
}  // namespace

TEST(LikelihoodField, DistanceIsEuclideanToTheNearestObstacleAndCapped) {
  GridMap m = emptyMap(50, 50);
  m.cells[25 * 50 + 25] = 100;
  const LikelihoodField f(m, 1.0);
  EXPECT_NEAR(f.distance(2.55, 2.55), 0.0, 1e-6);
  EXPECT_NEAR(f.distance(2.55 + 0.3, 2.55 + 0.4), 0.5, 1e-5);
  EXPECT_NEAR(f.distance(0.05, 0.05), 1.0, 1e-6);  // capped at max_dist
  EXPECT_NEAR(f.distance(-3.0, 0.0), 1.0, 1e-6);   // outside the map
}

TEST(LikelihoodField, FreeCellsExcludeUnknownAndObstacles) {
  GridMap m = emptyMap(4, 1);
  m.cells = {0, -1, 100, 10};
  const LikelihoodField f(m, 1.0);
  EXPECT_EQ(f.freeCells().size(), 2u);
  EXPECT_TRUE(f.isFree(0.05, 0.05));
  EXPECT_FALSE(f.isFree(0.15, 0.05));
  EXPECT_FALSE(f.isFree(0.25, 0.05));
}

TEST(LikelihoodField, RefusesMalformedMaps) {
  GridMap m = emptyMap(4, 4);
  m.cells.pop_back();
  EXPECT_THROW(LikelihoodField(m, 1.0), std::invalid_argument);
  EXPECT_THROW(LikelihoodField(emptyMap(4, 4), 0.0), std::invalid_argument);
}

TEST(LikelihoodField, FarAndNonFinitePointsAreOutsideTheMap) {
  // Particles of an initial pose with a huge variance land at 1e150 m: no int overflow.
  const LikelihoodField f(emptyMap(4, 4), 1.0);
  for (const double v : {1e150, -1e150, 3e9, std::nan(""), std::numeric_limits<double>::infinity()}) {
    EXPECT_NEAR(f.distance(v, 0.05), 1.0, 1e-6) << v;
    EXPECT_NEAR(f.distance(0.05, v), 1.0, 1e-6) << v;
    EXPECT_FALSE(f.isFree(v, v)) << v;
  }
  EXPECT_TRUE(f.isFree(0.05, 0.05));
}

TEST(LikelihoodField, AnInitialPoseMustLieOnTheMapAndSpreadLessThanIt) {
  GridMap m = emptyMap(40, 30);  // 4 m x 3 m: a 5 m diagonal
  EXPECT_EQ(amcl_lite::initialPoseProblem(m, 1.0, 1.0, 0.25, 0.25), "");
  EXPECT_NE(amcl_lite::initialPoseProblem(m, 1e6, 1.0, 0.25, 0.25).find("is off the map (x 0.00 to 4.00"),
            std::string::npos);
  EXPECT_NE(amcl_lite::initialPoseProblem(m, 1.0, 1.0, 1e300, 0.25).find("wider than the map's diagonal (5.0 m)"),
            std::string::npos);
  EXPECT_NE(amcl_lite::initialPoseProblem(m, 1.0, 1.0, 0.25, 26.0).find("wider"), std::string::npos);
  EXPECT_NE(amcl_lite::initialPoseProblem(m, std::nan(""), 1.0, 0.25, 0.25), "");
}
