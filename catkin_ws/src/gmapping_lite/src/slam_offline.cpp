// slam_offline: run the SLAM library over a bag's scans and tf as fast as possible and write
// the map in map_server's format (PGM + YAML), plus optionally the trajectory.
//
//   rosrun gmapping_lite slam_offline BAG [--out map] [--scan /scan] [--base-frame base_link]
//       [--odom-frame odom] [--trajectory traj.csv] [--param name=value ...]
#include <ros/time.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <sensor_msgs/LaserScan.h>
#include <tf2/buffer_core.h>
#include <tf2_msgs/TFMessage.h>

#include "gmapping_lite/occupancy.h"
#include "gmapping_lite/odometry_period.h"
#include "gmapping_lite/param_table.h"
#include "gmapping_lite/particle_filter.h"
#include "gmapping_lite/scan_pipeline.h"
#include "rosbook_env/map_files.h"

using namespace gmapping_lite;  // NOLINT: a program, not a header

namespace {

struct Options {
  std::string bag, out = "map", scan_topic = "/scan", base_frame = "base_link",
                   odom_frame = "odom", trajectory;
  SlamParams params;
  bool max_range_set = false, max_urange_set = false;
  double tilt_tolerance = 0.1;
};

constexpr const char* kUsage =
    "usage: slam_offline BAG [--out BASE] [--scan TOPIC] [--base-frame F] [--odom-frame F] "
    "[--trajectory CSV] [--param NAME=VALUE ...]\n";

int usage(const char* why) {
  std::fprintf(stderr, "slam_offline: %s\n%s", why, kUsage);
  return 2;
}

// --help: what the tool does and its options, on stdout, exit 0.
int help() {
  std::printf(
      "%s\n"
      "gmapping_lite's SLAM over a recorded bag, every scan in order, as fast as the machine goes;\n"
      "writes the map as BASE.pgm and BASE.yaml (map_server's format).\n\n"
      "  --out BASE         the map's file names without extension (default: map)\n"
      "  --scan TOPIC       the sensor_msgs/LaserScan topic (default: /scan)\n"
      "  --base-frame F     the robot's frame (default: base_link)\n"
      "  --odom-frame F     odometry's frame (default: odom)\n"
      "  --trajectory CSV   also write the SLAM path: stamp,x,y,yaw per update\n"
      "  --param NAME=VALUE a slam_gmapping parameter (e.g. particles=30, maxUrange=6.0); repeatable\n",
      kUsage);
  return 0;
}

bool parse(int argc, char** argv, Options* o, std::string* error) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](std::string* dst) {
      if (i + 1 >= argc) {
        *error = a + " needs a value";
        return false;
      }
      *dst = argv[++i];
      return true;
    };
    if (a == "--out") {
      if (!value(&o->out)) return false;
    } else if (a == "--scan") {
      if (!value(&o->scan_topic)) return false;
    } else if (a == "--base-frame") {
      if (!value(&o->base_frame)) return false;
    } else if (a == "--odom-frame") {
      if (!value(&o->odom_frame)) return false;
    } else if (a == "--trajectory") {
      if (!value(&o->trajectory)) return false;
    } else if (a == "--param") {
      std::string kv;
      if (!value(&kv)) return false;
      const auto eq = kv.find('=');
      char* end = nullptr;
      const double v = eq == std::string::npos ? 0 : std::strtod(kv.c_str() + eq + 1, &end);
      if (eq == std::string::npos || !end || *end || !std::isfinite(v) ||
          !setParam(&o->params, kv.substr(0, eq), v)) {
        *error = "bad --param '" + kv + "' (expected NAME=NUMBER with a slam_gmapping name)";
        return false;
      }
      const std::string problem = valueProblem(kv.substr(0, eq), v);
      if (!problem.empty()) {
        *error = problem;
        return false;
      }
      o->max_range_set |= kv.substr(0, eq) == "maxRange";
      o->max_urange_set |= kv.substr(0, eq) == "maxUrange";
    } else if (!a.empty() && a[0] == '-') {
      *error = "unknown option " + a;
      return false;
    } else if (o->bag.empty()) {
      o->bag = a;
    } else {
      *error = "more than one bag given";
      return false;
    }
  }
  if (o->bag.empty()) *error = "no bag given";
  if (error->empty() && o->out.empty()) *error = "--out needs a base name, e.g. --out mymap";
  if (error->empty()) *error = paramProblem(o->params, o->max_range_set, o->max_urange_set);
  return error->empty();
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  std::string error;
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") return help();
  }
  if (!parse(argc, argv, &o, &error)) return usage(error.c_str());
  ros::Time::init();
  const auto wall_start = std::chrono::steady_clock::now();
  // The outputs' folders are checked before the bag is read: a long bag's SLAM would
  // otherwise be run to the end only to find nowhere to write it.
  for (const std::string& target : {o.out + ".pgm", o.trajectory}) {
    const std::filesystem::path folder = std::filesystem::path(target).parent_path();
    if (target.empty() || folder.empty() || std::filesystem::is_directory(folder)) continue;
    if (std::filesystem::exists(folder)) {
      std::fprintf(stderr, "slam_offline: cannot write %s: %s is a file, not a folder\n", target.c_str(),
                   folder.c_str());
    } else {
      std::fprintf(stderr, "slam_offline: cannot write %s: folder %s does not exist (create it with: mkdir -p '%s')\n",
                   target.c_str(), folder.c_str(), folder.c_str());
    }
    return 1;
  }

  rosbag::Bag bag;
  try {
    bag.open(o.bag, rosbag::bagmode::Read);
  } catch (const std::exception& e) {
    // A file that starts like a bag but cannot be opened is most often an unfinished
    // recording (rosbag record killed, or still writing NAME.bag.active): name the repair.
    char magic[13] = {};
    std::FILE* file = std::fopen(o.bag.c_str(), "rb");
    const bool bag_like = file && std::fread(magic, 1, 12, file) == 12 && std::string(magic) == "#ROSBAG V2.0";
    if (file) std::fclose(file);
    std::fprintf(stderr, "slam_offline: cannot open %s: %s%s\n", o.bag.c_str(), e.what(),
                 bag_like ? " (an unfinished recording? `rosbag reindex BAG` rebuilds its index)" : "");
    return 1;
  }
  // Pass 1: all of tf, so each scan can be placed whatever order the bag holds it in. The
  // buffer must hold the span of the transforms' stamps, not of the bag's record times: a
  // simulation recorded without use_sim_time runs faster than the recorder's wall clock.
  // Odometry's sample period from the stamps of the odom -> base transforms, for the filter's
  // timing term (OdometryPeriod).
  rosbag::View tf_view(bag, rosbag::TopicQuery(std::vector<std::string>{"/tf", "/tf_static"}));
  std::vector<std::pair<tf2_msgs::TFMessage::ConstPtr, bool>> tf_messages;
  double first_tf = 0, last_tf = 0;
  bool have_stamp = false;
  OdometryPeriod odometry_period;
  const std::string odom_frame = stripSlash(o.odom_frame), base_frame = stripSlash(o.base_frame);
  for (const rosbag::MessageInstance& m : tf_view) {
    const auto msg = m.instantiate<tf2_msgs::TFMessage>();
    if (!msg) continue;
    const bool is_static = m.getTopic() == "/tf_static";
    for (const auto& t : msg->transforms) {
      if (is_static) continue;
      const double stamp = t.header.stamp.toSec();
      if (stripSlash(t.header.frame_id) == odom_frame && stripSlash(t.child_frame_id) == base_frame)
        odometry_period.add(stamp);
      first_tf = have_stamp ? std::min(first_tf, stamp) : stamp;
      last_tf = have_stamp ? std::max(last_tf, stamp) : stamp;
      have_stamp = true;
    }
    tf_messages.emplace_back(msg, is_static);
  }
  tf2::BufferCore tf(ros::Duration(std::max(10.0, last_tf - first_tf + 10.0)));
  for (const auto& [msg, is_static] : tf_messages)
    for (const auto& t : msg->transforms) tf.setTransform(t, "bag", is_static);
  const std::size_t tf_count = tf_messages.size();
  tf_messages.clear();

  rosbag::View scan_view(bag, rosbag::TopicQuery(std::vector<std::string>{o.scan_topic}));
  if (scan_view.size() == 0) {
    // Name the LaserScan topics the bag does hold, so a scan recorded under another name
    // (base_scan, /robot/scan) is one --scan away.
    std::string scans;
    rosbag::View all(bag);
    for (const rosbag::ConnectionInfo* c : all.getConnections()) {
      if (c->datatype == "sensor_msgs/LaserScan" && scans.find(c->topic + ",") == std::string::npos)
        scans += c->topic + ",";
    }
    if (!scans.empty()) scans.pop_back();
    std::fprintf(stderr, "slam_offline: %s has no messages on %s%s\n", o.bag.c_str(), o.scan_topic.c_str(),
                 scans.empty() ? " (nor any sensor_msgs/LaserScan topic: record the laser, e.g. rosbag record -O data.bag /scan /tf)"
                               : (" (its LaserScan topics: " + scans + "; choose one with --scan TOPIC)").c_str());
    return 1;
  }
  ScanPipelineOptions options;
  options.base_frame = o.base_frame;
  options.odom_frame = o.odom_frame;
  options.tilt_tolerance = o.tilt_tolerance;
  options.params = o.params;
  options.max_range_set = o.max_range_set;
  options.max_urange_set = o.max_urange_set;
  ScanPipeline pipeline(options, lookupIn(tf));
  pipeline.setOdometryPeriod(odometry_period.period());
  int loop_attempts = 0, loops = 0, rebuilds = 0;
  int unstamped_said = 0, no_odometry_said = 0;  // the first few of each are said
  double first_stamp = -1, last_stamp = 0;
  for (const rosbag::MessageInstance& m : scan_view) {
    const auto scan = m.instantiate<sensor_msgs::LaserScan>();
    if (!scan) continue;
    const ScanOutcome r = pipeline.process(*scan);
    for (const ScanNote& note : r.notes)
      if (note.warning) std::fprintf(stderr, "slam_offline: %s\n", note.text.c_str());
    switch (r.result) {
      case ScanResult::kNoMount:
      case ScanResult::kBadMount:
        // A bag's tf is all there: a laser it cannot place now it never will.
        std::fprintf(stderr, "slam_offline: %s\n", r.problem.c_str());
        return 1;
      case ScanResult::kMalformed:
        if (r.report) std::fprintf(stderr, "slam_offline: %s\n", r.problem.c_str());
        continue;
      case ScanResult::kUnstamped:
        if (++unstamped_said <= 3) std::fprintf(stderr, "slam_offline: %s\n", r.problem.c_str());
        continue;
      case ScanResult::kNoOdometry:
        if (++no_odometry_said <= 3)
          std::fprintf(stderr, "slam_offline: %s\n", r.problem.c_str());
        continue;
      case ScanResult::kUpdated:
      case ScanResult::kNotUpdated:
        break;
    }
    const double stamp = scan->header.stamp.toSec();
    if (first_stamp < 0) first_stamp = stamp;
    last_stamp = stamp;
    loop_attempts += r.update.loop.tried;
    loops += r.update.loop.accepted;
    rebuilds += r.update.map_rebuilt;
  }
  const ParticleFilter* filter = pipeline.filter();
  const int scans = pipeline.scans(), dropped = pipeline.withoutOdometry(),
            malformed = pipeline.malformed() + pipeline.unstamped();
  if (!filter) {
    std::fprintf(stderr,
                 "slam_offline: no scan could be placed (%d scans, %d without odometry, %d "
                 "malformed)\n",
                 scans, dropped, malformed);
    return 1;
  }
  const Particle& best = filter->best();
  const SlamParams& params = pipeline.params();
  const OccupancyMap occ = toOccupancy(best.map, params.xmin, params.ymin, params.xmax,
                                       params.ymax, params.occ_thresh);
  if (!writeMapFiles(occ, o.out, &error)) {
    std::fprintf(stderr, "slam_offline: %s\n", error.c_str());
    return 1;
  }
  if (!o.trajectory.empty()) {
    std::vector<const TrajectoryNode*> nodes;
    for (auto n = best.trajectory.get(); n; n = n->parent.get()) nodes.push_back(n);
    std::string csv = "stamp,x,y,theta\n";
    char line[128];
    for (auto n = nodes.rbegin(); n != nodes.rend(); ++n) {
      std::snprintf(line, sizeof(line), "%.6f,%.6f,%.6f,%.6f\n", (*n)->stamp, (*n)->pose.x,
                    (*n)->pose.y, (*n)->pose.theta);
      csv += line;
    }
    try {
      rosbook_env::write_files_atomically({{o.trajectory, csv}});
    } catch (const rosbook_env::MapFileError& e) {
      std::fprintf(stderr, "slam_offline: %s\n", e.what());
      return 1;
    }
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  const double duration = last_stamp - first_stamp;
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const double cpu = double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                     1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  // The odometry period the motion prior's timing term used (OdometryPeriod over the bag's
  // odom -> base transforms), so a user can check it against the robot's odometry rate.
  char period[32];
  std::snprintf(period, sizeof(period), "%.3f", odometry_period.period());  // rounded, not cut
  const std::string odometry_note =
      odometry_period.known() ? "odometry every " + std::string(period) + " s (measured)"
                              : "odometry period unknown (no " + odom_frame + " -> " + base_frame + " on /tf)";
  std::printf("slam_offline: %d scans (%d without odometry, %d malformed), %d updates, "
              "%zu tf messages; "
              "%.1f s of data in %.2f s (%.1fx real time, cpu %.2f s); map %dx%d written to "
              "%s.pgm/.yaml; loop closures %d of %d tried (%d redrew the map); %s\n",
              scans, dropped, malformed, filter->updates(), tf_count, duration, wall,
              wall > 0 ? duration / wall : 0.0, cpu, occ.width, occ.height, o.out.c_str(), loops,
              loop_attempts, rebuilds, odometry_note.c_str());
  return 0;
}
