#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "gmapping_lite/occupancy.h"

using gmapping_lite::GridMap;
using gmapping_lite::OccupancyMap;

namespace {
std::string readAll(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}
}  // namespace

TEST(Occupancy, CellsAreMinusOneZeroOrHundredWithinBounds) {
  GridMap map(0.1);
  map.traceBeam(0.05, 0.05, 0.55, 0.05, true);
  const OccupancyMap occ = gmapping_lite::toOccupancy(map, -1, -1, 1, 1, 0.25);
  EXPECT_EQ(occ.width, 20);
  EXPECT_EQ(occ.height, 20);
  EXPECT_DOUBLE_EQ(occ.origin_x, -1.0);
  EXPECT_DOUBLE_EQ(occ.origin_y, -1.0);
  EXPECT_EQ(occ.at(10, 10), 0);    // (0.05, 0.05)
  EXPECT_EQ(occ.at(15, 10), 100);  // (0.55, 0.05)
  EXPECT_EQ(occ.at(0, 0), -1);
}

TEST(Occupancy, GrowsBeyondTheInitialBounds) {
  GridMap map(0.1);
  map.traceBeam(0.05, 0.05, 3.05, 0.05, true);
  const OccupancyMap occ = gmapping_lite::toOccupancy(map, -1, -1, 1, 1, 0.25);
  EXPECT_GE(occ.origin_x + occ.width * occ.resolution, 3.1 - 1e-9);
  EXPECT_EQ(occ.at(static_cast<int>((3.05 - occ.origin_x) / 0.1), 10), 100);
}

TEST(Occupancy, WritesMapServerPgmAndYamlAtomically) {
  GridMap map(0.1);
  map.traceBeam(0.05, 0.05, 0.55, 0.05, true);
  const OccupancyMap occ = gmapping_lite::toOccupancy(map, -1, -1, 1, 1, 0.25);
  char dir[] = "/tmp/occXXXXXX";
  ASSERT_NE(mkdtemp(dir), nullptr);
  const std::string base = std::string(dir) + "/map";
  std::string error;
  ASSERT_TRUE(gmapping_lite::writeMapFiles(occ, base, &error)) << error;
  const std::string yaml = readAll(base + ".yaml");
  EXPECT_NE(yaml.find("image: map.pgm"), std::string::npos);
  EXPECT_NE(yaml.find("resolution: 0.100000"), std::string::npos);
  EXPECT_NE(yaml.find("origin: [-1.000000, -1.000000, 0.000000]"), std::string::npos);
  EXPECT_NE(yaml.find("negate: 0"), std::string::npos);
  EXPECT_NE(yaml.find("occupied_thresh: 0.65"), std::string::npos);
  EXPECT_NE(yaml.find("free_thresh: 0.196"), std::string::npos);
  const std::string pgm = readAll(base + ".pgm");
  const std::size_t header = pgm.size() - 400;
  ASSERT_EQ(pgm.substr(0, 3), "P5\n");
  // Row 0 of the image is the top (y = +1); map row 10 is image row 9.
  EXPECT_EQ(static_cast<unsigned char>(pgm[header + 9 * 20 + 10]), 254);
  EXPECT_EQ(static_cast<unsigned char>(pgm[header + 9 * 20 + 15]), 0);
  EXPECT_EQ(static_cast<unsigned char>(pgm[header + 0]), 205);
  // No temporary files are left behind.
  EXPECT_EQ(std::system((std::string("test $(ls ") + dir + " | wc -l) -eq 2").c_str()), 0);
  std::system((std::string("rm -rf ") + dir).c_str());
}

TEST(Occupancy, UnwritableDirectoryIsAnErrorNotACrash) {
  GridMap map(0.1);
  const OccupancyMap occ = gmapping_lite::toOccupancy(map, -1, -1, 1, 1, 0.25);
  std::string error;
  EXPECT_FALSE(gmapping_lite::writeMapFiles(occ, "/nonexistent/dir/map", &error));
  EXPECT_FALSE(error.empty());
}
