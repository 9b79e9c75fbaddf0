#include "bullet_turtlebot/grid_boxes.hpp"

#include <cstddef>

namespace bullet_turtlebot {

std::vector<CellRect> merge_cells(const std::vector<std::uint8_t>& occupied, int width, int height) {
  std::vector<CellRect> rects;
  std::vector<std::uint8_t> used(occupied.size(), 0);
  auto free_cell = [&](int c, int r) {
    const std::size_t i = static_cast<std::size_t>(r) * width + c;
    return occupied[i] && !used[i];
  };
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col) {
      if (!free_cell(col, row)) continue;
      // Widest run along the row, then grow downwards while the whole run is available.
      int w = 1;
      while (col + w < width && free_cell(col + w, row)) ++w;
      int h = 1;
      for (; row + h < height; ++h) {
        bool full = true;
        for (int c = col; c < col + w && full; ++c) full = free_cell(c, row + h);
        if (!full) break;
      }
      for (int r = row; r < row + h; ++r) {
        for (int c = col; c < col + w; ++c) used[static_cast<std::size_t>(r) * width + c] = 1;
      }
      rects.push_back(CellRect{col, row, w, h});
    }
  }
  return rects;
}

}  // namespace bullet_turtlebot
