// slam_gmapping: gmapping's ROS interface around the gmapping_lite particle filter.
//
// Subscribes `scan`; reads odometry from tf (odom_frame -> base_frame at each scan's stamp)
// and the laser's mounting (base_frame -> scan frame, once per frame and beam layout).
// Publishes `map` and `map_metadata` (latched), `~entropy`, tf map_frame -> odom_frame,
// `/diagnostics` (scan counts, with each map), and serves `dynamic_map`.
//
// Scans are mapped by a worker thread that always takes the newest scan: when updates take
// longer than the scan period (a busy machine, a fast simulator) the scans it could not get
// to are skipped and counted, never queued up stale.
#include <ros/ros.h>
#include <rosbook_env/master_watch.h>

#include <atomic>
#include <cstdint>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/GetMap.h>
#include <nav_msgs/MapMetaData.h>
#include <nav_msgs/OccupancyGrid.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Float64.h>
#include <diagnostic_msgs/DiagnosticArray.h>
#include <tf2/LinearMath/Quaternion.h>
#include <tf2/utils.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>

#include "gmapping_lite/newest_slot.h"
#include "gmapping_lite/occupancy.h"
#include "gmapping_lite/param_table.h"
#include "gmapping_lite/particle_filter.h"
#include "gmapping_lite/scan_input.h"
#include "gmapping_lite/tuning_file.h"

namespace gmapping_lite {

class SlamGmappingNode {
 public:
  SlamGmappingNode() : private_("~"), tf_listener_(tf_buffer_) {
    private_.param<std::string>("base_frame", base_frame_, "base_link");
    private_.param<std::string>("map_frame", map_frame_, "map");
    private_.param<std::string>("odom_frame", odom_frame_, "odom");
    base_frame_ = stripSlash(base_frame_);
    map_frame_ = stripSlash(map_frame_);
    odom_frame_ = stripSlash(odom_frame_);
    private_.param("throttle_scans", throttle_scans_, 1);
    private_.param("map_update_interval", map_update_interval_, 5.0);
    private_.param("transform_publish_period", transform_publish_period_, 0.05);
    private_.param("tf_wait", tf_wait_, 0.5);  // wall seconds to wait for odometry tf
    private_.param("tilt_tolerance", tilt_tolerance_, 0.1);  // each name in nodeParamNames()
    warnUnusedParams();
    std::string problem;
    for (const auto& e : paramTable()) {
      double value;
      if (private_.getParam(e.name, value)) {
        e.set(&params_, value);
      } else if (problem.empty() && private_.hasParam(e.name)) {
        std::string text;  // set, but not a number (e.g. _delta:=abc)
        private_.getParam(e.name, text);
        problem = std::string(e.name) + " is '" + text + "': it must be a number";
      }
    }
    max_range_set_ = private_.hasParam("maxRange");
    max_urange_set_ = private_.hasParam("maxUrange");
    if (problem.empty()) problem = paramProblem(params_, max_range_set_, max_urange_set_);
    if (problem.empty() && throttle_scans_ < 1) problem = "throttle_scans must be 1 or more";
    if (problem.empty() && !(map_update_interval_ > 0.0 && std::isfinite(map_update_interval_)))
      problem = "map_update_interval must be a number of seconds above 0";
    if (!problem.empty()) {
      const std::string line = "slam_gmapping: ~" + problem +
                               " (set it with rosparam set /slam_gmapping/NAME VALUE, or _NAME:=VALUE)";
      ROS_FATAL("%s", line.c_str());
      throw std::invalid_argument(line);
    }

    map_pub_ = node_.advertise<nav_msgs::OccupancyGrid>("map", 1, true);
    metadata_pub_ = node_.advertise<nav_msgs::MapMetaData>("map_metadata", 1, true);
    entropy_pub_ = private_.advertise<std_msgs::Float64>("entropy", 1, true);
    diagnostics_pub_ = node_.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10);
    map_service_ = node_.advertiseService("dynamic_map", &SlamGmappingNode::onMapRequest, this);
    scan_thread_ = std::thread([this] {
      while (auto scan = scans_.take()) processScan(*scan);
    });
    scan_sub_ = node_.subscribe("scan", 20, &SlamGmappingNode::onScan, this);
    if (transform_publish_period_ > 0.0)
      tf_thread_ = std::thread([this] { publishTransformLoop(); });
    ROS_INFO("slam_gmapping: waiting for scans on %s; frames %s -> %s -> %s -> <laser>; "
             "%d particles, linearUpdate %.2f m, angularUpdate %.2f rad, lskip %d",
             scan_sub_.getTopic().c_str(), map_frame_.c_str(), odom_frame_.c_str(),
             base_frame_.c_str(), params_.particles, params_.linear_update,
             params_.angular_update, params_.matcher.lskip);
  }

  ~SlamGmappingNode() {
    stopping_ = true;
    scans_.close();
    if (scan_thread_.joinable()) scan_thread_.join();
    if (tf_thread_.joinable()) tf_thread_.join();
  }

 private:
  // Once, at start-up: a private parameter the node does not read (a misspelt name, or one of
  // gmapping's that gmapping_lite has no use for) would otherwise be ignored silently.
  void warnUnusedParams() const {
    std::vector<std::string> all, mine;
    if (!ros::param::getParamNames(all)) return;
    const std::string prefix = private_.getNamespace() + "/";
    for (const std::string& name : all)
      if (name.rfind(prefix, 0) == 0) mine.push_back(name.substr(prefix.size()));
    std::string names;
    for (const std::string& name : unusedParams(mine)) names += (names.empty() ? "~" : ", ~") + name;
    if (!names.empty())
      ROS_WARN("slam_gmapping: ignoring private parameters that gmapping_lite does not read: "
               "%s (check the spelling; gmapping_lite's README lists those it reads)",
               names.c_str());
  }

  static std::string stripSlash(const std::string& frame) {
    return !frame.empty() && frame[0] == '/' ? frame.substr(1) : frame;
  }

  // Wait (wall time, briefly) until tf can answer target <- source at `stamp`.
  bool waitForTransform(const std::string& target, const std::string& source,
                        const ros::Time& stamp, geometry_msgs::TransformStamped* out,
                        std::string* error) {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(tf_wait_);
    while (true) {
      try {
        *out = tf_buffer_.lookupTransform(target, source, stamp);
        return true;
      } catch (const tf2::TransformException& e) {
        *error = e.what();
      }
      if (ros::WallTime::now() > deadline || !ros::ok()) return false;
      ros::WallDuration(0.005).sleep();
    }
  }

  // The laser's beams in the base frame, cached per frame and beam layout.
  const LaserGeometry* laserGeometry(const sensor_msgs::LaserScan& scan) {
    const std::string frame = stripSlash(scan.header.frame_id);
    auto it = lasers_.find(frame);
    const bool known = it != lasers_.end();
    if (known && it->second.count == scan.ranges.size() &&
        it->second.angle_min == scan.angle_min &&
        it->second.angle_increment == scan.angle_increment)
      return &it->second.geometry;
    if (known && it->second.count != scan.ranges.size()) {
      ROS_WARN("slam_gmapping: the scan on frame %s changed from %zu to %zu beams; "
               "rebuilding the beam table and carrying on",
               frame.c_str(), it->second.count, scan.ranges.size());
    }
    geometry_msgs::TransformStamped mount;
    std::string error;
    // The mounting is static: ask for the latest, waiting briefly for it to appear.
    if (!waitForTransform(base_frame_, frame, ros::Time(0), &mount, &error)) {
      ROS_WARN_THROTTLE(5.0,
                        "slam_gmapping: cannot place the laser: no transform from base frame "
                        "'%s' to laser frame '%s' (%s). Is robot_state_publisher or a static "
                        "transform publisher running? Dropping scans until it appears.",
                        base_frame_.c_str(), frame.c_str(), error.c_str());
      return nullptr;
    }
    tf2::Transform laser_in_base;
    tf2::fromMsg(mount.transform, laser_in_base);
    LaserEntry entry;
    entry.count = scan.ranges.size();
    entry.angle_min = scan.angle_min;
    entry.angle_increment = scan.angle_increment;
    if (!makeLaserGeometry(laser_in_base, scan.angle_min, scan.angle_increment,
                           scan.ranges.size(), tilt_tolerance_, &entry.geometry, &error)) {
      ROS_ERROR_THROTTLE(5.0, "slam_gmapping: laser frame '%s': %s", frame.c_str(), error.c_str());
      return nullptr;
    }
    ROS_INFO("slam_gmapping: laser '%s' at (%.3f, %.3f) in '%s', %zu beams from %.3f to %.3f "
             "rad%s",
             frame.c_str(), entry.geometry.origin.x, entry.geometry.origin.y,
             base_frame_.c_str(), entry.count, scan.angle_min,
             scan.angle_min + scan.angle_increment * (double(entry.count) - 1),
             upsideDown(laser_in_base) ? " (mounted upside down: beam angles mirrored)" : "");
    lasers_[frame] = entry;
    return &lasers_[frame].geometry;
  }

  // The subscriber's callback only hands the scan to the worker (processScan).
  void onScan(const sensor_msgs::LaserScan::ConstPtr& scan) {
    const int received = ++scans_received_;
    if ((received - 1) % throttle_scans_ != 0) return;
    scans_.put(scan);
  }

  void processScan(const sensor_msgs::LaserScan::ConstPtr& scan) {
    // The scan's number among those the mapper took (1 = the first): in the log, a gap
    // between two updates' numbers that is shorter than their time apart shows skipped scans.
    const int index = ++scans_taken_;
    const std::uint64_t skipped = scans_.skipped();
    // At most one line every 30 wall seconds: a fast simulator runs many scan periods a
    // second, and the count in each line says how it went since.
    const ros::WallTime wall_now = ros::WallTime::now();
    if (skipped > skipped_reported_ && wall_now >= next_skip_warning_) {  // the first at once
      ROS_WARN("slam_gmapping: falling behind the scans: %llu of %llu skipped so far (each "
               "mapped the newest); updates take longer than the scan period. A lower "
               "simulator speed, fewer particles or a higher throttle_scans lets it keep up",
               static_cast<unsigned long long>(skipped),
               static_cast<unsigned long long>(scans_.offered()));
      skipped_reported_ = skipped;
      next_skip_warning_ = wall_now + ros::WallDuration(30.0);
    }
    if (scan->header.stamp.isZero()) {
      ROS_WARN_THROTTLE(5.0, "slam_gmapping: ignoring a scan stamped 0 (is the publisher "
                             "waiting for /clock?)");
      return;
    }
    if (const auto problem =
            scanProblem(scan->angle_min, scan->angle_max, scan->angle_increment,
                        scan->ranges.size(), scan->range_min, scan->range_max)) {
      if (malformed_.count(scan->header.stamp.toSec()))
        ROS_WARN("slam_gmapping: dropping a malformed scan on frame '%s' at %.3f: %s; "
                 "malformed scans dropped so far: %d",
                 scan->header.frame_id.c_str(), scan->header.stamp.toSec(), problem->c_str(),
                 malformed_.total());
      return;
    }
    const LaserGeometry* laser = laserGeometry(*scan);
    if (!laser) return;
    geometry_msgs::TransformStamped odom_tf;
    std::string error;
    if (!waitForTransform(odom_frame_, base_frame_, scan->header.stamp, &odom_tf, &error)) {
      ++scans_dropped_;
      ROS_WARN_THROTTLE(5.0,
                        "slam_gmapping: no odometry: transform from '%s' to '%s' at the scan's "
                        "stamp %.3f is not available (%s); %d scans dropped so far",
                        odom_frame_.c_str(), base_frame_.c_str(), scan->header.stamp.toSec(),
                        error.c_str(), scans_dropped_);
      return;
    }
    if (!filter_) {
      const std::string note =
          rangeDefaults(&params_, scan->range_max, max_range_set_, max_urange_set_);
      if (!note.empty()) ROS_WARN("slam_gmapping: %s", note.c_str());
      filter_ = std::make_unique<ParticleFilter>(params_);
      ROS_INFO("slam_gmapping: maxRange %.2f m, maxUrange %.2f m",
               params_.matcher.max_range, params_.matcher.max_urange);
    }
    const Pose2 odom(odom_tf.transform.translation.x, odom_tf.transform.translation.y,
                     tf2::getYaw(odom_tf.transform.rotation));
    const Ranges ranges = toRanges(scan->ranges, scan->range_min, scan->range_max);
    const UpdateReport report = filter_->addScan(odom, scan->header.stamp.toSec(), *laser, ranges);
    {
      std::lock_guard<std::mutex> lock(tf_mutex_);
      if (latest_stamp_ < scan->header.stamp) latest_stamp_ = scan->header.stamp;
    }
    if (!report.processed) return;

    {
      std::lock_guard<std::mutex> lock(tf_mutex_);
      map_to_odom_ = filter_->mapToOdom();
      have_transform_ = true;
    }
    std_msgs::Float64 entropy;
    entropy.data = filter_->entropy();
    entropy_pub_.publish(entropy);
    const std::string failed =
        report.failed_matches
            ? ", " + std::to_string(report.failed_matches) + " matches below minimumScore"
            : "";
    ROS_INFO("slam_gmapping: update %d (scan %d, t=%.2f): best pose (%.3f, %.3f, %.3f), "
             "Neff %.1f/%d%s, match score %.0f%s",
             report.update_index, index, scan->header.stamp.toSec(),
             report.best_pose.x, report.best_pose.y, report.best_pose.theta, report.neff,
             params_.particles, report.resampled ? ", resampled" : "", report.best_score,
             failed.c_str());
    if (!have_map_ || (scan->header.stamp - last_map_update_).toSec() >= map_update_interval_) {
      publishMap(scan->header.stamp);
      publishDiagnostics(scan->header.stamp, report.update_index + 1);
      last_map_update_ = scan->header.stamp;
    }
  }

  // Scan counts on /diagnostics, with each map: WARN while scans are being skipped.
  void publishDiagnostics(const ros::Time& stamp, int updates) {
    const std::uint64_t offered = scans_.offered(), skipped = scans_.skipped();
    diagnostic_msgs::DiagnosticStatus status;
    status.name = ros::this_node::getName() + ": scans";
    status.hardware_id = "none";
    const std::uint64_t new_skips = skipped - skipped_at_last_diagnostics_;
    skipped_at_last_diagnostics_ = skipped;
    status.level = new_skips ? diagnostic_msgs::DiagnosticStatus::WARN
                             : diagnostic_msgs::DiagnosticStatus::OK;
    status.message = new_skips ? "falling behind: " + std::to_string(new_skips) +
                                     " scans skipped since the last map"
                               : "keeping up with the scans";
    auto add = [&status](const std::string& key, std::uint64_t value) {
      diagnostic_msgs::KeyValue kv;
      kv.key = key;
      kv.value = std::to_string(value);
      status.values.push_back(kv);
    };
    add("scans received", static_cast<std::uint64_t>(scans_received_.load()));
    add("scans offered to the mapper", offered);
    add("scans skipped (fell behind)", skipped);
    add("scans malformed", static_cast<std::uint64_t>(malformed_.total()));
    add("scans without odometry", static_cast<std::uint64_t>(scans_dropped_));
    add("updates", static_cast<std::uint64_t>(updates));
    diagnostic_msgs::DiagnosticArray array;
    array.header.stamp = stamp;
    array.status.push_back(status);
    diagnostics_pub_.publish(array);
  }

  void publishMap(const ros::Time& stamp) {
    const OccupancyMap occ = toOccupancy(filter_->best().map, params_.xmin, params_.ymin,
                                         params_.xmax, params_.ymax, params_.occ_thresh);
    nav_msgs::OccupancyGrid grid;
    grid.header.stamp = stamp;
    grid.header.frame_id = map_frame_;
    grid.info.map_load_time = stamp;
    grid.info.resolution = static_cast<float>(occ.resolution);
    grid.info.width = static_cast<uint32_t>(occ.width);
    grid.info.height = static_cast<uint32_t>(occ.height);
    grid.info.origin.position.x = occ.origin_x;
    grid.info.origin.position.y = occ.origin_y;
    grid.info.origin.orientation.w = 1.0;
    grid.data = occ.data;
    {
      std::lock_guard<std::mutex> lock(map_mutex_);
      map_ = grid;
      have_map_ = true;
    }
    map_pub_.publish(grid);
    metadata_pub_.publish(grid.info);
    ROS_INFO("slam_gmapping: published map %dx%d at %.3f m/cell, origin (%.2f, %.2f)",
             occ.width, occ.height, occ.resolution, occ.origin_x, occ.origin_y);
  }

  bool onMapRequest(nav_msgs::GetMap::Request&, nav_msgs::GetMap::Response& res) {
    std::lock_guard<std::mutex> lock(map_mutex_);
    if (!have_map_) return false;
    res.map = map_;
    return true;
  }

  void publishTransformLoop() {
    tf2_ros::TransformBroadcaster broadcaster;
    // Sim-time aware, so a faster-than-real-time clock still gets transforms every period.
    const ros::Duration period(transform_publish_period_);
    while (!stopping_ && ros::ok()) {
      geometry_msgs::TransformStamped t;
      bool ready;
      {
        std::lock_guard<std::mutex> lock(tf_mutex_);
        ready = have_transform_;
        // Stamped ahead, as gmapping does, so lookups at "now" need no extrapolation; never
        // stamped from a clock that has not started.
        ros::Time base = latest_stamp_;
        const ros::Time now = ros::Time::now();
        if (now > base) base = now;
        t.header.stamp = base + ros::Duration(transform_publish_period_);
        t.transform.translation.x = map_to_odom_.x;
        t.transform.translation.y = map_to_odom_.y;
        tf2::Quaternion q;
        q.setRPY(0, 0, map_to_odom_.theta);
        t.transform.rotation.x = q.x();
        t.transform.rotation.y = q.y();
        t.transform.rotation.z = q.z();
        t.transform.rotation.w = q.w();
      }
      if (ready) {
        t.header.frame_id = map_frame_;
        t.child_frame_id = odom_frame_;
        broadcaster.sendTransform(t);
      }
      period.sleep();
    }
  }

  struct LaserEntry {
    std::size_t count = 0;
    float angle_min = 0, angle_increment = 0;
    LaserGeometry geometry;
  };

  ros::NodeHandle node_, private_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  ros::Publisher map_pub_, metadata_pub_, entropy_pub_, diagnostics_pub_;
  ros::ServiceServer map_service_;
  ros::Subscriber scan_sub_;

  std::string base_frame_, map_frame_, odom_frame_;
  int throttle_scans_ = 1;
  double map_update_interval_ = 5.0, transform_publish_period_ = 0.05, tf_wait_ = 0.5;
  double tilt_tolerance_ = 0.1;
  SlamParams params_;
  bool max_range_set_ = false, max_urange_set_ = false;
  std::unique_ptr<ParticleFilter> filter_;
  std::map<std::string, LaserEntry> lasers_;
  std::atomic<int> scans_received_{0};
  int scans_dropped_ = 0;
  NewestSlot<sensor_msgs::LaserScan::ConstPtr> scans_;
  int scans_taken_ = 0;  // by the worker thread only
  std::thread scan_thread_;
  std::uint64_t skipped_reported_ = 0, skipped_at_last_diagnostics_ = 0;
  ros::WallTime next_skip_warning_;
  ScanDrops malformed_{5.0};  // warn at most every 5 s of scan time, each line with the count

  std::mutex tf_mutex_;
  Pose2 map_to_odom_;
  bool have_transform_ = false;
  ros::Time latest_stamp_;
  std::thread tf_thread_;
  std::atomic<bool> stopping_{false};

  std::mutex map_mutex_;
  nav_msgs::OccupancyGrid map_;
  bool have_map_ = false;
  ros::Time last_map_update_;
};

}  // namespace gmapping_lite

int main(int argc, char** argv) {
  // Diagnostics appear line by line even when stdout is a file or a pipe.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  ros::init(argc, argv, "slam_gmapping");
  std::unique_ptr<gmapping_lite::SlamGmappingNode> node;
  try {
    node = std::make_unique<gmapping_lite::SlamGmappingNode>();
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  const rosbook_env::MasterWatch master_watch;  // re-registers with a restarted roscore
  // Two threads: the service and the scan callback must not block each other for long.
  ros::AsyncSpinner spinner(2);
  spinner.start();
  ros::waitForShutdown();
  return 0;
}
