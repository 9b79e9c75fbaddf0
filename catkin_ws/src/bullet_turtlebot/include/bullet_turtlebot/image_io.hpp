// Reading Netpbm images (PGM/PPM), the format map_server and map_saver use.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace bullet_turtlebot {

// An 8-bit grey image, row 0 at the top (as in the file).
struct GreyImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  // row-major, width * height
};

class ImageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads P2/P5 (grey) and P3/P6 (colour, averaged like map_server does), 8 or 16 bit.
// Throws ImageError with the problem (not the file name; callers add it).
GreyImage read_pnm(const std::string& path);

// Writing a map: rosbook_env/map_files.h (bullet_turtlebot::write_map).

}  // namespace bullet_turtlebot
