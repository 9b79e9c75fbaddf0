// Ground truth for scoring: the world rasterised into a map_server map (YAML + PGM).
#pragma once

#include <string>

#include "bullet_turtlebot/image_io.hpp"
#include "bullet_turtlebot/types.hpp"
#include "bullet_turtlebot/world.hpp"

namespace bullet_turtlebot {

struct MapImage {
  GreyImage image;  // 254 free, 0 occupied
  double resolution = 0.05;
  Pose2D origin;    // lower-left corner, yaw 0
};

// Cells whose centre lies inside a solid taller than min_height are occupied; bounds are
// the solids' bounds plus `margin`.
MapImage rasterize_world(const World& world, double resolution, double margin = 0.5,
                         double min_height = 0.0);

// Writes NAME.pgm and NAME.yaml (map_saver's format) with rosbook_env's one writer
// (map_files.h: atomic, the YAML last); throws rosbook_env::MapFileError naming the file.
void write_map(const MapImage& map, const std::string& base_name);

}  // namespace bullet_turtlebot
