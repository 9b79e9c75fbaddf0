// map_server's map files (NAME.pgm + NAME.yaml, map_saver's format), written atomically: the
// one C++ writer, used by gmapping_lite (slam_offline) and bullet_turtlebot (world_to_map).
// map_server's Python map_saver writes the same bytes (map_io.save_map). No ROS inside.
#ifndef ROSBOOK_ENV_MAP_FILES_H
#define ROSBOOK_ENV_MAP_FILES_H

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rosbook_env {

class MapFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// map_saver's pixel values.
constexpr std::uint8_t kPgmFree = 254, kPgmOccupied = 0, kPgmUnknown = 205;

// A map as map_server reads it: `pixels` row-major with row 0 the map's top (the order of
// the file), `origin_*` the pose of the bottom-left pixel's corner (REP 103, metres, rad).
struct MapImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;
  double resolution = 0.05;  // metres per pixel
  double origin_x = 0.0, origin_y = 0.0, origin_yaw = 0.0;
};

// map_saver's rule for nav_msgs/OccupancyGrid values (row 0 at the map's bottom): 0..free
// free, >= occupied occupied, the rest (-1 among them) unknown. Returns the pixels top row
// first. Defaults are map_saver's (--free 0, --occ 65).
std::vector<std::uint8_t> pixels_from_occupancy(const std::vector<std::int8_t>& cells, int width,
                                                int height, int occupied = 65, int free = 0);

// Binary P5, with "# comment" as the second line when `comment` is not empty.
std::string encode_pgm(const MapImage& map, const std::string& comment);

// map_saver's YAML, as the book prints it ("image: NAME.pgm", "resolution: 0.050000", ...);
// a name YAML would not read back as itself is written double-quoted.
std::string map_yaml_text(const std::string& image_name, const MapImage& map);

// Writes BASE.pgm and BASE.yaml: both in full to temporary files in BASE's folder first,
// then renamed into place, the YAML last, so a reader never finds a YAML naming an image
// that is not complete. On any failure (bad map, missing or unwritable folder, full disk)
// throws MapFileError naming the file and the cause; the old pair, if any, is untouched and
// no temporary file is left. Returns the two paths written.
std::pair<std::string, std::string> write_map_files(const std::string& base, const MapImage& map,
                                                    const std::string& pgm_comment);

// {path, bytes} pairs: each written and fsynced to a temporary file in its own folder, and
// only when all are complete renamed over their targets, in the order given. A failure
// before the renames leaves every target as it was and removes the temporary files.
void write_files_atomically(const std::vector<std::pair<std::string, std::string>>& files);

}  // namespace rosbook_env

#endif  // ROSBOOK_ENV_MAP_FILES_H
