// A world description: a map_server-style occupancy image extruded into walls, plus
// primitives (boxes, cylinders) and the robot's start pose. Parsed from YAML.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "bullet_turtlebot/types.hpp"

namespace bullet_turtlebot {

struct BoxSpec {
  Pose2D pose;  // centre in the world frame
  double size_x = 1.0, size_y = 1.0, size_z = 1.0;
  Color color;
};

struct CylinderSpec {
  double x = 0.0, y = 0.0;
  double radius = 0.5, height = 1.0;
  Color color;
};

// Occupied cells of the map image after map_server's thresholding.
struct GridSpec {
  int width = 0;
  int height = 0;
  double resolution = 0.05;
  Pose2D origin;  // pose of the lower-left corner of the image (map_server `origin`)
  std::vector<std::uint8_t> occupied;  // row-major, row 0 = top row of the image
  bool is_occupied(int col, int row) const { return occupied[static_cast<size_t>(row) * width + col] != 0; }
};

struct WorldSpec {
  std::string source;  // the file it came from, for messages
  GridSpec grid;       // empty (0x0) when the world has no image
  double wall_height = 1.0;
  Color wall_color{0.75f, 0.72f, 0.66f};
  std::vector<BoxSpec> boxes;
  std::vector<CylinderSpec> cylinders;
  bool has_start = false;
  Pose2D start;
};

// Every problem with a world file, its message naming the file and the problem.
class WorldFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

WorldSpec load_world_file(const std::string& path);

// A bare name ("maze") names a shipped world in worlds_dir; anything with a slash or ending
// in ".yaml" is a path and is returned as it is.
std::string resolve_world_path(const std::string& world, const std::string& worlds_dir);

// Parses YAML text; `source` names it in messages, relative image paths resolve from base_dir.
WorldSpec parse_world_yaml(const std::string& text, const std::string& source, const std::string& base_dir);

// map_server's trinary semantics reduced to "occupied": p = (255 - v) / 255 (v / 255 with
// negate) and occupied when p > occupied_thresh.
std::vector<std::uint8_t> threshold_occupied(const std::vector<std::uint8_t>& pixels, bool negate,
                                             double occupied_thresh);

}  // namespace bullet_turtlebot
