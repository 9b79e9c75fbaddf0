// slam_bench: time the filter on the synthetic office tour (10 Hz scans, odometry that
// drifts) and print a markdown table: time per processed scan, real-time factor, accuracy.
// One core; scans that move the robot too little for an update still count in the real-time
// factor, since a live node receives them too.
#include <time.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <ros/package.h>

#include "gmapping_lite/particle_filter.h"
#include "synthetic.h"
#include "gmapping_lite/tuning_file.h"

using namespace gmapping_lite;  // NOLINT: a program, not a header

namespace {

double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

struct Row {
  std::string label;
  int particles;
  int beams;
  SlamParams params;
};

// The Turtlebot tuning: the package's config/turtlebot.yaml, found as rosrun finds the program.
SlamParams turtlebot() {
  SlamParams p;
  const std::string package = ros::package::getPath("gmapping_lite");
  if (package.empty()) {
    std::fprintf(stderr, "slam_bench: cannot find the package gmapping_lite: source the "
                         "workspace's setup.bash first\n");
    std::exit(2);
  }
  const std::string problem = loadTuning(package + "/config/turtlebot.yaml", &p);
  if (!problem.empty()) {
    std::fprintf(stderr, "slam_bench: %s\n", problem.c_str());
    std::exit(2);
  }
  return p;
}

SlamParams defaults() {
  SlamParams p;  // slam_gmapping's defaults; ranges from the 8 m laser
  p.matcher.max_range = p.matcher.max_urange = 7.99;
  return p;
}

const char* const kUsage =
    "usage: slam_bench [--quick | --book | --only PARTICLES BEAMS]\n"
    "  --quick: the first row only; --book: the book's settings only;\n"
    "  --only: one row of the defaults (PARTICLES 1..1000, BEAMS 2..10000)\n";

int usageError(const std::string& problem) {
  std::fprintf(stderr, "slam_bench: %s\n%s", problem.c_str(), kUsage);
  return 2;
}

// A whole number in [lo, hi], all of `text`; false for anything else.
bool wholeNumber(const char* text, long lo, long hi, int* out) {
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || value < lo || value > hi) return false;
  *out = static_cast<int>(value);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  const std::string mode = args.empty() ? "" : args[0];
  if (mode == "-h" || mode == "--help") {
    std::printf("%s", kUsage);
    return 0;
  }
  const bool quick = mode == "--quick";
  const bool only = mode == "--only";
  const bool book = mode == "--book";
  const std::size_t expected = only ? 3 : mode.empty() ? 0 : 1;
  if (!mode.empty() && !quick && !only && !book)
    return usageError("unknown argument '" + mode + "'");
  if (args.size() != expected) return usageError("wrong number of arguments");
  int only_particles = 0, only_beams = 0;
  // The particle bound is slam_gmapping's (param_table.cpp); a laser needs two beams for an
  // angle increment, and 10000 bounds the synthetic scans' memory.
  if (only && !wholeNumber(argv[2], 1, 1000, &only_particles))
    return usageError(std::string("--only PARTICLES must be a whole number in [1, 1000], got '") +
                      argv[2] + "'");
  if (only && !wholeNumber(argv[3], 2, 10000, &only_beams))
    return usageError(std::string("--only BEAMS must be a whole number in [2, 10000], got '") +
                      argv[3] + "'");
  const SyntheticWorld world = SyntheticWorld::office();
  std::vector<Row> rows;
  for (int beams : {320, 640})
    for (int particles : {30, 80}) {
      SlamParams p = defaults();
      p.particles = particles;
      rows.push_back({"defaults", particles, beams, p});
    }
  {
    SlamParams p = defaults();
    p.angular_update = 0.1;
    p.linear_update = 0.1;
    p.matcher.lskip = 10;
    rows.push_back({"book: angular/linearUpdate 0.1, lskip 10", 30, 640, p});
  }
  {
    const SlamParams tuned = turtlebot();
    SlamParams p = tuned;
    p.particles = 30;
    rows.push_back({"Turtlebot tuning, 30 particles", 30, 640, p});
    rows.push_back({"Turtlebot tuning (config/turtlebot.yaml)", tuned.particles, 640, tuned});
  }
  if (quick) rows.resize(1);
  if (book) rows = {rows[4]};
  if (only) {
    SlamParams p = defaults();
    p.particles = only_particles;
    rows = {{"defaults", p.particles, only_beams, p}};
  }

  std::printf("## gmapping_lite SLAM (synthetic office tour, 10 Hz scans, one core)\n\n");
  std::printf("| settings | particles | beams | scans | updates | CPU ms per update | "
              "real-time factor | trajectory RMS (m) | odometry RMS (m) |\n");
  std::printf("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
  for (const Row& row : rows) {
    RunOptions options;
    options.beams = row.beams;
    const SyntheticRun run = simulateRun(world, officeTour(), options);
    ParticleFilter filter(row.params);
    // CPU time of this process: the machine may be shared, and the filter is single-threaded.
    const double start = cpuSeconds();
    for (const auto& s : run.steps) filter.addScan(s.odom, s.stamp, run.laser, s.ranges);
    const double wall = cpuSeconds() - start;
    const double span = run.steps.back().stamp - run.steps.front().stamp;
    // Accuracy of the best particle's trajectory against the truth, both from the start pose.
    std::vector<const TrajectoryNode*> nodes;
    for (auto n = filter.best().trajectory.get(); n; n = n->parent.get()) nodes.push_back(n);
    double se = 0, so = 0;
    std::size_t k = 0, matched = 0;
    for (auto n = nodes.rbegin(); n != nodes.rend(); ++n) {
      while (k < run.steps.size() && run.steps[k].stamp < (*n)->stamp - 1e-9) ++k;
      if (k >= run.steps.size()) break;
      const Pose2 truth = run.steps[k].truth.relativeTo(run.steps.front().truth);
      se += std::pow((*n)->pose.x - truth.x, 2) + std::pow((*n)->pose.y - truth.y, 2);
      so += std::pow(run.steps[k].odom.x - truth.x, 2) + std::pow(run.steps[k].odom.y - truth.y, 2);
      ++matched;
    }
    std::printf("| %s | %d | %d | %zu | %d | %.1f | %.1fx | %.3f | %.3f |\n", row.label.c_str(),
                row.particles, row.beams, run.steps.size(), filter.updates(),
                1000.0 * wall / std::max(1, filter.updates()), span / wall,
                std::sqrt(se / double(std::max<std::size_t>(1, matched))),
                std::sqrt(so / double(std::max<std::size_t>(1, matched))));
    std::fflush(stdout);
  }
  std::printf("\nReal-time factor: seconds of data per CPU second of processing, one thread "
              "(target: 20x on the defaults with 30 particles). RMS: the best particle's "
              "trajectory vs the truth.\n");
  return 0;
}
