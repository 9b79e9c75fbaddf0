// The tuning file (config/turtlebot.yaml) and slam_gmapping's parameter names as a whole.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "gmapping_lite/param_table.h"
#include "gmapping_lite/tuning_file.h"

namespace gmapping_lite {
namespace {

std::string writeFile(const std::string& name, const std::string& text) {
  const std::string path = testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

TEST(TuningFile, TheTurtlebotTuningLoadsWithEveryKeyUsed) {
  SlamParams p;
  EXPECT_EQ(loadTuning(TURTLEBOT_TUNING, &p), "");
  EXPECT_EQ(p.particles, 80);
  EXPECT_EQ(p.linear_update, 0.5);
  EXPECT_EQ(p.angular_update, 0.436);
  EXPECT_EQ(p.minimum_score, 200);
  EXPECT_EQ(p.matcher.max_range, 8.0);
  EXPECT_EQ(p.matcher.max_urange, 6.0);
  EXPECT_EQ(p.motion.srr, 0.01);
  EXPECT_EQ(p.motion.stt, 0.02);
  EXPECT_EQ(p.xmin, -10.0);
  EXPECT_EQ(p.ymax, 10.0);
}

TEST(TuningFile, NamesTheFileAndWhatIsWrong) {
  SlamParams p;
  EXPECT_NE(loadTuning("/nonexistent/tuning.yaml", &p).find("/nonexistent/tuning.yaml: cannot read"),
            std::string::npos);
  const std::string list = writeFile("list.yaml", "- 1\n- 2\n");
  EXPECT_EQ(loadTuning(list, &p), list + ": the tuning file is not a map of parameter names to values");
  const std::string unused = writeFile("unused.yaml", "srr: 0.01\nllsamplerange: 0.01\n");
  EXPECT_EQ(loadTuning(unused, &p), unused + ": llsamplerange is not a slam_gmapping parameter");
  const std::string word = writeFile("word.yaml", "srr: little\n");
  EXPECT_EQ(loadTuning(word, &p), word + ": srr must be a number");
  const std::string bad = writeFile("bad.yaml", "particles: 0\n");
  EXPECT_EQ(loadTuning(bad, &p).rfind(bad + ": particles is 0: it must be", 0), 0u);
}

TEST(TuningFile, UnusedParamsAreThoseNeitherTheFilterNorTheNodeReads) {
  EXPECT_EQ(unusedParams({"srr", "base_frame", "llsamplerange", "tf_wait", "partcles"}),
            (std::vector<std::string>{"llsamplerange", "partcles"}));
  for (const auto& e : paramTable()) EXPECT_TRUE(unusedParams({e.name}).empty()) << e.name;
  for (const auto& n : nodeParamNames()) EXPECT_TRUE(unusedParams({n}).empty()) << n;
}

}  // namespace
}  // namespace gmapping_lite
