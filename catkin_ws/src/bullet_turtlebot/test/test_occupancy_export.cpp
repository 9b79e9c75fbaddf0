#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "bullet_turtlebot/occupancy_export.hpp"
#include "bullet_turtlebot/world_spec.hpp"
#include "test_helpers.hpp"

using namespace bullet_turtlebot;

TEST(OccupancyExport, BoxRasterisedInMapServerFormat) {
  World world(testing_helpers::box_world(Pose2D{1.0, 0.5, 0.0}, 1.0, 0.5));
  const MapImage map = rasterize_world(world, 0.1, 0.5);
  EXPECT_NEAR(map.origin.x, 0.0, 1e-6);
  EXPECT_NEAR(map.origin.y, -0.25, 1e-6);
  EXPECT_EQ(map.image.width, 20);
  EXPECT_EQ(map.image.height, 15);
  int occupied = 0;
  for (auto p : map.image.pixels) {
    EXPECT_TRUE(p == 0 || p == 254);
    occupied += p == 0;
  }
  EXPECT_EQ(occupied, 10 * 5);
  const testing_helpers::ScopedTempDir dir("bt_export");
  const std::string base = dir.path() + "/truth";
  write_map(map, base);
  std::ifstream yaml(base + ".yaml");
  std::stringstream text;
  text << yaml.rdbuf();
  EXPECT_NE(text.str().find("image: truth.pgm"), std::string::npos);
  EXPECT_NE(text.str().find("negate: 0"), std::string::npos);
  EXPECT_NE(text.str().find("occupied_thresh: 0.65"), std::string::npos);
  EXPECT_NE(text.str().find("free_thresh: 0.196"), std::string::npos);
  // Round trip: the written map is a valid world whose walls cover the box.
  const WorldSpec again = load_world_file(base + ".yaml");
  int cells = 0;
  for (auto c : again.grid.occupied) cells += c;
  EXPECT_EQ(cells, 50);
}

TEST(OccupancyExport, RefusesAMarginOrHeightItCannotDraw) {
  const World world(testing_helpers::box_world(Pose2D{}, 1.0, 1.0));
  EXPECT_THROW(rasterize_world(world, 0.1, std::nan("")), std::invalid_argument);
  EXPECT_THROW(rasterize_world(world, 0.1, -5.0), std::invalid_argument);
  EXPECT_THROW(rasterize_world(world, 0.1, 0.5, std::nan("")), std::invalid_argument);
  // So many cells that an int would overflow: refused, not drawn as a 1 x 1 map.
  EXPECT_THROW(rasterize_world(world, 0.1, 1e9), std::invalid_argument);
}
