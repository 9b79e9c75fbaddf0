#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "bullet_turtlebot/image_io.hpp"
#include "bullet_turtlebot/world_spec.hpp"
#include "test_helpers.hpp"

using namespace bullet_turtlebot;

namespace {

void write_file(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// The error message for loading `text`, or "" when it loads.
std::string error_of(const std::string& text, const std::string& dir) {
  try {
    parse_world_yaml(text, dir + "/w.yaml", dir);
  } catch (const WorldFileError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(WorldSpec, MapServerThresholds) {
  // v = 0 black (occupied), 254 free, 205 unknown, 100: p = 0.608 < 0.65 -> not occupied.
  const std::vector<std::uint8_t> pixels{0, 254, 205, 100, 80};
  EXPECT_EQ(threshold_occupied(pixels, false, 0.65), (std::vector<std::uint8_t>{1, 0, 0, 0, 1}));
  EXPECT_EQ(threshold_occupied(pixels, true, 0.65), (std::vector<std::uint8_t>{0, 1, 1, 0, 0}));
}

TEST(WorldSpec, LoadsImagePrimitivesAndStart) {
  const testing_helpers::ScopedTempDir temp("bt_world_spec");
  const std::string& dir = temp.path();
  const std::string pixels{0, char(254), char(254), char(254), char(254), char(254), char(254), 0};
  write_file(dir + "/m.pgm", "P5\n4 2\n255\n" + pixels);
  write_file(dir + "/w.yaml",
             "image: m.pgm\nresolution: 0.5\norigin: [-1.0, -2.0, 0.0]\nnegate: 0\noccupied_thresh: 0.65\n"
             "free_thresh: 0.196\nwall_height: 2.0\nstart: [0.5, 0.25, 1.0]\n"
             "boxes:\n  - {pose: [1, 2, 0.5], size: [1, 2, 0.5], color: [1, 0, 0]}\n"
             "cylinders:\n  - {position: [3, 4], radius: 0.2, height: 0.7}\n");
  const WorldSpec spec = load_world_file(dir + "/w.yaml");
  EXPECT_EQ(spec.grid.width, 4);
  EXPECT_EQ(spec.grid.height, 2);
  EXPECT_DOUBLE_EQ(spec.grid.resolution, 0.5);
  EXPECT_DOUBLE_EQ(spec.grid.origin.y, -2.0);
  EXPECT_TRUE(spec.grid.is_occupied(0, 0));
  EXPECT_TRUE(spec.grid.is_occupied(3, 1));
  EXPECT_FALSE(spec.grid.is_occupied(1, 0));
  EXPECT_DOUBLE_EQ(spec.wall_height, 2.0);
  ASSERT_TRUE(spec.has_start);
  EXPECT_DOUBLE_EQ(spec.start.yaw, 1.0);
  ASSERT_EQ(spec.boxes.size(), 1u);
  EXPECT_FLOAT_EQ(spec.boxes[0].color.r, 1.0f);
  ASSERT_EQ(spec.cylinders.size(), 1u);
  EXPECT_DOUBLE_EQ(spec.cylinders[0].radius, 0.2);
}

TEST(WorldSpec, ErrorsNameTheFileAndTheProblem) {
  const testing_helpers::ScopedTempDir temp("bt_world_spec");
  const std::string& dir = temp.path();
  const std::string missing_file = dir + "/nope.yaml";
  try {
    load_world_file(missing_file);
    FAIL() << "no error for a missing file";
  } catch (const WorldFileError& e) {
    EXPECT_NE(std::string(e.what()).find(missing_file), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("cannot open"), std::string::npos) << e.what();
  }
  auto expect_error = [&](const std::string& text, const std::string& fragment) {
    const std::string error = error_of(text, dir);
    EXPECT_NE(error.find(dir + "/w.yaml"), std::string::npos) << "for: " << text << "\ngot: " << error;
    EXPECT_NE(error.find(fragment), std::string::npos) << "for: " << text << "\ngot: " << error;
  };
  expect_error("image: [unclosed\n", "YAML syntax error at line");
  expect_error("- just\n- a list\n", "expected a YAML mapping");
  expect_error("image: m.pgm\norigin: [0, 0, 0]\n", "missing key 'resolution'");
  expect_error("image: m.pgm\nresolution: -1\norigin: [0, 0, 0]\n", "'resolution' must be > 0");
  expect_error("image: m.pgm\nresolution: abc\norigin: [0, 0, 0]\n", "'resolution' must be a number");
  expect_error("image: m.pgm\nresolution: 0.05\norigin: [0, 0]\n", "'origin' must be a list of 3 numbers");
  expect_error("image: absent.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n", "absent.pgm': cannot open");
  expect_error("boxes:\n  - {pose: [0, 0, 0]}\n", "boxes[0] needs");
  expect_error("cylinders:\n  - {position: [0, 0], radius: -1, height: 1}\n", "cylinders[0].radius");
  expect_error("resolution: 0.05\n", "empty world");
  expect_error("image: m.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 2\n", "'negate' must be 0 or 1");
  expect_error("", "expected a YAML mapping");
  expect_error("resolution: 0.05\nstart: [0, 0]\nstart: [1, 1]\n", "key 'start' given twice (lines 2 and 3)");
  expect_error("cylinders:\n  - {position: [0, 0], radius: 1, radius: 2, height: 1}\n", "key 'radius' given twice");
  try {
    load_world_file(dir);
    FAIL() << "no error for a directory";
  } catch (const WorldFileError& e) {
    EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos) << e.what();
  }
  write_file(dir + "/bad.pgm", "P5\n4 x\n255\n");
  expect_error("image: bad.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n", "bad height");
  write_file(dir + "/short.pgm", "P5\n4 4\n255\nab");
  expect_error("image: short.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n", "truncated");
  write_file(dir + "/text.pgm", "hello");
  expect_error("image: text.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n", "not a PGM/PPM image");
}

TEST(ImageIo, ColourAndAsciiImagesAverageChannels) {
  const testing_helpers::ScopedTempDir temp("bt_world_spec");
  const std::string& dir = temp.path();
  write_file(dir + "/c.ppm", "P3\n2 1\n255\n0 0 0  255 255 252\n");
  const GreyImage c = read_pnm(dir + "/c.ppm");
  ASSERT_EQ(c.pixels.size(), 2u);
  EXPECT_EQ(c.pixels[0], 0);
  EXPECT_EQ(c.pixels[1], 254);
  write_file(dir + "/g.pgm", "P2\n# comment\n2 1\n15\n0 15\n");
  const GreyImage g = read_pnm(dir + "/g.pgm");
  EXPECT_EQ(g.pixels[1], 255);
}

TEST(WorldSpec, FarPlacesHugeSizesAndSpecialFilesAreRefused) {
  const testing_helpers::ScopedTempDir temp("bt_world_spec");
  const std::string& dir = temp.path();
  auto expect_error = [&](const std::string& text, const std::string& fragment) {
    const std::string error = error_of(text, dir);
    EXPECT_NE(error.find(fragment), std::string::npos) << "for: " << text << "\ngot: " << error;
  };
  const std::string box = "boxes:\n  - {pose: [3, 0, 0], size: [1, 1, 1]}\n";
  expect_error("start: [1e300, 0, 0]\n" + box, "'start' must be metres within 1e6 of the origin");
  expect_error("boxes:\n  - {pose: [1e7, 0, 0], size: [1, 1, 1]}\n", "boxes[0].pose' must be metres within 1e6");
  expect_error("boxes:\n  - {pose: [0, 0, 0], size: [1e300, 1, 1]}\n", "boxes[0].size must be positive metres");
  expect_error("cylinders:\n  - {position: [5, 0], radius: 1e300, height: 1}\n", "'cylinders[0].radius' must be at most 1e6");
  expect_error("cylinders:\n  - {position: [-2e6, 0], radius: 1, height: 1}\n", "'cylinders[0].position[0]' must be metres");
  expect_error("wall_height: 1e300\n" + box, "'wall_height' must be at most 1e6");
  write_file(dir + "/m.pgm", "P5\n4 4\n255\n" + std::string(16, char(254)));
  expect_error("image: m.pgm\nresolution: 0.05\norigin: [1e300, 0, 0]\n", "'origin' must be metres within 1e6");
  expect_error("image: m.pgm\nresolution: 1e300\norigin: [0, 0, 0]\n", "'resolution' must be at most 1e6");
  expect_error("image: m.pgm\nresolution: 1e6\norigin: [0, 0, 0]\n", "spans more than 2e6 metres");
  // A header declaring 20000 x 20000 16-bit colour pixels (2.4 GB) in a 20-byte file: refused
  // before anything is allocated, as is a plain PGM too short for its header.
  write_file(dir + "/huge.ppm", "P6\n20000 20000\n65535\n");
  expect_error("image: huge.ppm\nresolution: 0.05\norigin: [0, 0, 0]\n", "0 bytes left for a 20000 x 20000 image");
  write_file(dir + "/huge.pgm", "P2\n20000 20000\n255\n1 2 3\n");
  expect_error("image: huge.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n", "truncated pixel data");
  expect_error("image: /dev/zero\nresolution: 0.05\norigin: [0, 0, 0]\n", "not a regular file");
  try {
    load_world_file("/dev/zero");
    FAIL() << "no error for /dev/zero";
  } catch (const WorldFileError& e) {
    EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos) << e.what();
  }
}
