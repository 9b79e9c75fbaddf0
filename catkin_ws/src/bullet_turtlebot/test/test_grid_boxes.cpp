#include <gtest/gtest.h>

#include <random>

#include "bullet_turtlebot/grid_boxes.hpp"

using bullet_turtlebot::CellRect;
using bullet_turtlebot::merge_cells;

namespace {

// Every occupied cell covered exactly once, no free cell covered.
void expect_exact_cover(const std::vector<std::uint8_t>& occ, int w, int h, const std::vector<CellRect>& rects) {
  std::vector<int> cover(occ.size(), 0);
  for (const auto& r : rects) {
    ASSERT_GE(r.col, 0);
    ASSERT_GE(r.row, 0);
    ASSERT_LE(r.col + r.width, w);
    ASSERT_LE(r.row + r.height, h);
    for (int y = r.row; y < r.row + r.height; ++y)
      for (int x = r.col; x < r.col + r.width; ++x) ++cover[y * w + x];
  }
  for (size_t i = 0; i < occ.size(); ++i) EXPECT_EQ(cover[i], occ[i] ? 1 : 0) << "cell " << i;
}

}  // namespace

TEST(GridBoxes, FullGridIsOneBox) {
  std::vector<std::uint8_t> occ(20 * 10, 1);
  const auto rects = merge_cells(occ, 20, 10);
  ASSERT_EQ(rects.size(), 1u);
  EXPECT_EQ(rects[0].width, 20);
  EXPECT_EQ(rects[0].height, 10);
}

TEST(GridBoxes, EmptyGridHasNoBoxes) {
  std::vector<std::uint8_t> occ(30, 0);
  EXPECT_TRUE(merge_cells(occ, 6, 5).empty());
}

TEST(GridBoxes, RoomOutlineIsFourBoxes) {
  const int w = 50, h = 40;
  std::vector<std::uint8_t> occ(w * h, 0);
  for (int x = 0; x < w; ++x) occ[x] = occ[(h - 1) * w + x] = 1;
  for (int y = 0; y < h; ++y) occ[y * w] = occ[y * w + w - 1] = 1;
  const auto rects = merge_cells(occ, w, h);
  EXPECT_EQ(rects.size(), 4u);
  expect_exact_cover(occ, w, h, rects);
}

TEST(GridBoxes, RandomGridsAreCoveredExactlyAndMerged) {
  std::mt19937 rng(42);
  for (int trial = 0; trial < 20; ++trial) {
    const int w = 1 + rng() % 60, h = 1 + rng() % 60;
    std::vector<std::uint8_t> occ(w * h);
    for (auto& c : occ) c = (rng() % 3) == 0;
    const auto rects = merge_cells(occ, w, h);
    expect_exact_cover(occ, w, h, rects);
    size_t occupied = 0;
    for (auto c : occ) occupied += c;
    EXPECT_LE(rects.size(), occupied);
  }
}
