// The map-file writer: map_saver's bytes, the pair replaced atomically, and a failure that
// leaves the old pair as it was and no temporary file behind.
#include <dirent.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rosbook_env/map_files.h"

using rosbook_env::MapFileError;
using rosbook_env::MapImage;

namespace {

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

::testing::AssertionResult starts_with(const std::string& text, const std::string& start) {
  if (text.compare(0, start.size(), start) == 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not start with \"" << start
                                       << "\"";
}

void put_file(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// Every name in `folder`, dot files (the temporaries) included.
std::set<std::string> folder_entries(const std::string& folder) {
  std::set<std::string> names;
  DIR* dir = ::opendir(folder.c_str());
  if (!dir) return names;
  while (const dirent* entry = ::readdir(dir)) {
    const std::string name = entry->d_name;
    if (name != "." && name != "..") names.insert(name);
  }
  ::closedir(dir);
  return names;
}

class MapFilesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    char pattern[] = "/tmp/map_files_XXXXXX";
    ASSERT_NE(::mkdtemp(pattern), nullptr);
    folder_ = pattern;
  }
  void TearDown() override {
    ::chmod(folder_.c_str(), 0700);
    std::system(("rm -rf '" + folder_ + "'").c_str());
  }

  // 3 x 2: the top row free, occupied, unknown; the bottom row the other way round.
  static MapImage small_map() {
    MapImage map;
    map.width = 3;
    map.height = 2;
    map.pixels = {254, 0, 205, 205, 0, 254};
    map.resolution = 0.05;
    map.origin_x = -10.5;
    map.origin_y = -8.25;
    return map;
  }

  std::string folder_;
};

TEST_F(MapFilesTest, WritesMapSaversBytes) {
  const auto [pgm, yaml] = rosbook_env::write_map_files(folder_ + "/office", small_map(),
                                                        "CREATOR: test 0.050 m/pix");
  EXPECT_EQ(pgm, folder_ + "/office.pgm");
  EXPECT_EQ(yaml, folder_ + "/office.yaml");
  const std::vector<std::uint8_t> pixels = small_map().pixels;
  EXPECT_EQ(read_file(pgm), "P5\n# CREATOR: test 0.050 m/pix\n3 2\n255\n" +
                                std::string(pixels.begin(), pixels.end()));
  // The layout map_saver writes (map_server/map_yaml.py), as the book prints it.
  EXPECT_EQ(read_file(yaml),
            "image: office.pgm\n"
            "resolution: 0.050000\n"
            "origin: [-10.500000, -8.250000, 0.000000]\n"
            "negate: 0\n"
            "occupied_thresh: 0.65\n"
            "free_thresh: 0.196\n\n");
  EXPECT_EQ(folder_entries(folder_), (std::set<std::string>{"office.pgm", "office.yaml"}));
  struct stat st {};
  ASSERT_EQ(::stat(pgm.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0644u);
}

TEST_F(MapFilesTest, PgmWithoutCommentAndYamlWithoutMinusZero) {
  MapImage map = small_map();
  map.origin_x = -0.0;
  map.origin_yaw = 0.5;
  EXPECT_TRUE(starts_with(rosbook_env::encode_pgm(map, ""), "P5\n3 2\n255\n\xfe"));
  EXPECT_TRUE(starts_with(rosbook_env::map_yaml_text("m.pgm", map),
                          "image: m.pgm\nresolution: 0.050000\n"
                          "origin: [0.000000, -8.250000, 0.500000]\nnegate: 0\n"));
}

TEST_F(MapFilesTest, QuotesANameYamlWouldNotReadBack) {
  const MapImage map = small_map();
  EXPECT_TRUE(starts_with(rosbook_env::map_yaml_text("my map.pgm", map), "image: my map.pgm\n"));
  EXPECT_TRUE(starts_with(rosbook_env::map_yaml_text("#1.pgm", map), "image: \"#1.pgm\"\n"));
  EXPECT_TRUE(starts_with(rosbook_env::map_yaml_text("a: \"b\".pgm", map),
                          "image: \"a: \\\"b\\\".pgm\"\n"));
}

TEST_F(MapFilesTest, OccupancyValuesFollowMapSaversRule) {
  // Rows from the bottom (nav_msgs/OccupancyGrid); pixels from the top.
  const std::vector<std::int8_t> cells{-1, 0, 100, 64, 65, 1};
  EXPECT_EQ(rosbook_env::pixels_from_occupancy(cells, 3, 2),
            (std::vector<std::uint8_t>{205, 0, 205, 205, 254, 0}));
  EXPECT_THROW(rosbook_env::pixels_from_occupancy(cells, 4, 2), MapFileError);
  EXPECT_THROW(rosbook_env::pixels_from_occupancy(cells, 3, 2, 50, 50), MapFileError);
}

TEST_F(MapFilesTest, ReplacesAnOldPairWhole) {
  const std::string base = folder_ + "/map";
  put_file(base + ".pgm", "old image");
  put_file(base + ".yaml", "old yaml");
  rosbook_env::write_map_files(base, small_map(), "");
  EXPECT_EQ(read_file(base + ".pgm").substr(0, 3), "P5\n");
  EXPECT_EQ(read_file(base + ".yaml").substr(0, 16), "image: map.pgm\nr");
  EXPECT_EQ(folder_entries(folder_), (std::set<std::string>{"map.pgm", "map.yaml"}));
}

TEST_F(MapFilesTest, MissingFolderIsAnErrorNamingTheFix) {
  const std::string base = folder_ + "/no/such/map";
  try {
    rosbook_env::write_map_files(base, small_map(), "");
    FAIL() << "no error for a missing folder";
  } catch (const MapFileError& e) {
    EXPECT_NE(std::string(e.what()).find(base + ".pgm"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("mkdir -p"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(folder_entries(folder_).empty());
}

// The folder cannot be written: nothing new appears, the old pair stays as it was.
TEST_F(MapFilesTest, UnwritableFolderLeavesTheOldPairAndNoTemporary) {
  const std::string base = folder_ + "/map";
  put_file(base + ".pgm", "old image");
  put_file(base + ".yaml", "old yaml");
  ASSERT_EQ(::chmod(folder_.c_str(), 0555), 0);
  // Permission bits do not stop root: then the write runs in a child as nobody.
  const bool as_root = ::geteuid() == 0;
  const pid_t child = as_root ? ::fork() : 0;
  ASSERT_GE(child, 0);
  if (child == 0) {
    int outcome = 0;
    if (as_root && (::setgid(65534) != 0 || ::setuid(65534) != 0)) ::_exit(3);
    try {
      rosbook_env::write_map_files(base, small_map(), "");
      outcome = 1;
    } catch (const MapFileError& e) {
      outcome = std::string(e.what()).find("Permission denied") != std::string::npos ? 0 : 2;
    }
    if (as_root) ::_exit(outcome);
    EXPECT_EQ(outcome, 0);
  } else {
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status));
    ASSERT_NE(WEXITSTATUS(status), 3) << "cannot become nobody to test an unwritable folder";
    EXPECT_EQ(WEXITSTATUS(status), 0) << "1: wrote into a read-only folder; 2: wrong error";
  }
  EXPECT_EQ(read_file(base + ".pgm"), "old image");
  EXPECT_EQ(read_file(base + ".yaml"), "old yaml");
  EXPECT_EQ(folder_entries(folder_), (std::set<std::string>{"map.pgm", "map.yaml"}));
}

// The second file fails after the first was staged: the first's temporary goes too.
TEST_F(MapFilesTest, ALaterFailureRemovesTheEarlierTemporary) {
  put_file(folder_ + "/a", "old a");
  EXPECT_THROW(rosbook_env::write_files_atomically(
                   {{folder_ + "/a", "new a"}, {folder_ + "/missing/b", "new b"}}),
               MapFileError);
  EXPECT_EQ(read_file(folder_ + "/a"), "old a");
  EXPECT_EQ(folder_entries(folder_), (std::set<std::string>{"a"}));
}

TEST_F(MapFilesTest, AFolderInPlaceOfTheYamlFailsBeforeTheImageIsReplaced) {
  const std::string base = folder_ + "/map";
  put_file(base + ".pgm", "old image");
  ASSERT_EQ(::mkdir((base + ".yaml").c_str(), 0755), 0);
  EXPECT_THROW(rosbook_env::write_map_files(base, small_map(), ""), MapFileError);
  EXPECT_EQ(read_file(base + ".pgm"), "old image");
  EXPECT_EQ(folder_entries(folder_), (std::set<std::string>{"map.pgm", "map.yaml"}));
}

TEST_F(MapFilesTest, RefusesAMapItCannotDescribe) {
  MapImage map = small_map();
  map.pixels.pop_back();
  EXPECT_THROW(rosbook_env::write_map_files(folder_ + "/m", map, ""), MapFileError);
  map = small_map();
  map.resolution = 0.0;
  EXPECT_THROW(rosbook_env::write_map_files(folder_ + "/m", map, ""), MapFileError);
  map = small_map();
  map.origin_y = std::nan("");
  EXPECT_THROW(rosbook_env::write_map_files(folder_ + "/m", map, ""), MapFileError);
  EXPECT_THROW(rosbook_env::write_map_files(folder_ + "/", small_map(), ""), MapFileError);
  EXPECT_TRUE(folder_entries(folder_).empty());
}

}  // namespace
