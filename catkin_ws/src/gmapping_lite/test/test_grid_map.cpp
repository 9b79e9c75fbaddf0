#include <gtest/gtest.h>

#include "gmapping_lite/grid_map.h"

using gmapping_lite::Cell;
using gmapping_lite::CellIndex;
using gmapping_lite::GridMap;

TEST(GridMap, UnknownUntilObserved) {
  GridMap map(0.05);
  EXPECT_EQ(map.find(0, 0), nullptr);
  EXPECT_EQ(map.patchCount(), 0u);
  CellIndex lo, hi;
  EXPECT_FALSE(map.knownBounds(&lo, &hi));
}

TEST(GridMap, BeamFreesTheWayAndHitsTheEnd) {
  GridMap map(0.1);
  map.traceBeam(0.05, 0.05, 1.05, 0.05, true);
  for (int i = 0; i < 10; ++i) {
    const Cell* c = map.find(i, 0);
    ASSERT_NE(c, nullptr) << i;
    EXPECT_EQ(c->visits, 1u);
    EXPECT_EQ(c->hits, 0u);
    EXPECT_DOUBLE_EQ(c->occupancy(), 0.0);
  }
  const Cell* end = map.find(10, 0);
  ASSERT_NE(end, nullptr);
  EXPECT_EQ(end->hits, 1u);
  EXPECT_DOUBLE_EQ(end->occupancy(), 1.0);
  // The hit's position inside the cell is kept (sub-cell accuracy for matching).
  EXPECT_NEAR(end->sum_dx, 0.0, 1e-6);
  EXPECT_NEAR(end->sum_dy, 0.0, 1e-6);
}

TEST(GridMap, MissLeavesEndCellFree) {
  GridMap map(0.1);
  map.traceBeam(0.05, 0.05, 0.05, 0.55, false);
  EXPECT_EQ(map.find(0, 5)->hits, 0u);
  EXPECT_EQ(map.find(0, 5)->visits, 1u);
}

TEST(GridMap, GrowsInEveryDirectionIncludingNegative) {
  GridMap map(0.05);
  map.edit(0, 0).visits = 1;
  map.edit(-500, 700).visits = 2;
  map.edit(900, -300).visits = 3;
  EXPECT_EQ(map.find(0, 0)->visits, 1u);
  EXPECT_EQ(map.find(-500, 700)->visits, 2u);
  EXPECT_EQ(map.find(900, -300)->visits, 3u);
  CellIndex lo, hi;
  ASSERT_TRUE(map.knownBounds(&lo, &hi));
  EXPECT_LE(lo.x, -500);
  EXPECT_LE(lo.y, -300);
  EXPECT_GT(hi.x, 900);
  EXPECT_GT(hi.y, 700);
}

TEST(GridMap, CopiesShareUntilWritten) {
  GridMap a(0.05);
  for (int i = 0; i < 200; ++i) a.edit(i, i).hits = 1;
  const std::size_t patches = a.patchCount();
  GridMap b = a;
  EXPECT_EQ(b.sharedPatchCount(), patches);
  b.edit(0, 0).hits = 7;  // un-shares exactly one patch
  EXPECT_EQ(a.find(0, 0)->hits, 1u);
  EXPECT_EQ(b.find(0, 0)->hits, 7u);
  EXPECT_EQ(b.sharedPatchCount(), patches - 1);
  EXPECT_EQ(a.find(150, 150)->hits, 1u);
}
