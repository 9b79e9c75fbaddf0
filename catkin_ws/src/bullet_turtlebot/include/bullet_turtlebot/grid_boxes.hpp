// Merging occupied grid cells into few axis-aligned rectangles (greedy), so the Bullet world
// holds hundreds of boxes instead of hundreds of thousands of cells.
#pragma once

#include <cstdint>
#include <vector>

namespace bullet_turtlebot {

struct CellRect {
  int col = 0, row = 0;       // top-left cell (row 0 = top row)
  int width = 0, height = 0;  // in cells
};

// Each occupied cell ends up in exactly one rectangle; no rectangle covers a free cell.
std::vector<CellRect> merge_cells(const std::vector<std::uint8_t>& occupied, int width, int height);

}  // namespace bullet_turtlebot
