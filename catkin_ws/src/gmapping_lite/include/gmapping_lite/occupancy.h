// Turning a particle's grid into a published map, and writing map_server's PGM + YAML.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gmapping_lite/grid_map.h"

namespace gmapping_lite {

struct OccupancyMap {
  int width = 0, height = 0;        // cells
  double resolution = 0.05;         // m per cell
  double origin_x = 0, origin_y = 0;  // world position of cell (0, 0)'s corner
  std::vector<int8_t> data;         // row-major from (origin), -1 unknown / 0 free / 100 occupied

  int8_t at(int i, int j) const { return data[static_cast<std::size_t>(j) * width + i]; }
};

// The map over [xmin, xmax] x [ymin, ymax], grown to include every observed cell.
OccupancyMap toOccupancy(const GridMap& map, double xmin, double ymin, double xmax, double ymax,
                         double occ_thresh);

// map_saver format: PGM P5 (254 free, 0 occupied, 205 unknown, row 0 at the top) and YAML,
// by rosbook_env's one writer (map_files.h: atomic, the YAML last). Returns false with
// `error` set; the old files are then untouched.
bool writeMapFiles(const OccupancyMap& map, const std::string& base, std::string* error);

}  // namespace gmapping_lite
