#include "slam_gmapping_node.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <nav_msgs/MapMetaData.h>
#include <std_msgs/Float64.h>
#include <tf2/LinearMath/Quaternion.h>
#include <tf2/exceptions.h>
#include <tf2_ros/transform_broadcaster.h>

#include "gmapping_lite/occupancy.h"
#include "gmapping_lite/param_table.h"
#include "gmapping_lite/tuning_file.h"

namespace gmapping_lite {

SlamGmappingNode::SlamGmappingNode() : private_("~"), tf_listener_(tf_buffer_) {
  ScanPipelineOptions options;
  private_.param<std::string>("base_frame", options.base_frame, "base_link");
  private_.param<std::string>("map_frame", map_frame_, "map");
  private_.param<std::string>("odom_frame", options.odom_frame, "odom");
  map_frame_ = stripSlash(map_frame_);
  private_.param("throttle_scans", throttle_scans_, 1);
  private_.param("map_update_interval", map_update_interval_, 5.0);
  private_.param("transform_publish_period", transform_publish_period_, 0.05);
  private_.param("tf_wait", tf_wait_, 0.5);  // wall seconds to wait for odometry tf
  private_.param("tilt_tolerance", options.tilt_tolerance, 0.1);  // each in nodeParamNames()
  warnUnusedParams();
  std::string problem;
  for (const auto& e : paramTable()) {
    XmlRpc::XmlRpcValue raw;
    if (!private_.getParam(e.name, raw)) continue;
    double value = 0;
    const auto type = raw.getType();
    if (type == XmlRpc::XmlRpcValue::TypeDouble) {
      value = static_cast<double>(raw);
    } else if (type == XmlRpc::XmlRpcValue::TypeInt) {
      value = static_cast<int>(raw);
    } else if (type == XmlRpc::XmlRpcValue::TypeBoolean && e.bounds.whole && e.bounds.hi == 1) {
      value = static_cast<bool>(raw) ? 1 : 0;  // a switch (~loop_closure): true / false
    } else {
      if (problem.empty()) {  // set, but not a number (e.g. _delta:=abc)
        std::ostringstream text;
        if (type == XmlRpc::XmlRpcValue::TypeString) text << static_cast<std::string>(raw);
        else raw.write(text);
        problem = std::string(e.name) + " is '" + text.str() + "': it must be a number";
      }
      continue;
    }
    // Checked before it is stored: an integer field would cut 2.5 particles to 2.
    if (problem.empty()) problem = entryProblem(e, value);
    if (problem.empty()) e.set(&options.params, value);
  }
  options.max_range_set = private_.hasParam("maxRange");
  options.max_urange_set = private_.hasParam("maxUrange");
  if (problem.empty())
    problem = paramProblem(options.params, options.max_range_set, options.max_urange_set);
  if (problem.empty() && throttle_scans_ < 1) problem = "throttle_scans must be 1 or more";
  if (problem.empty() && !(map_update_interval_ > 0.0 && std::isfinite(map_update_interval_)))
    problem = "map_update_interval must be a number of seconds above 0";
  if (!problem.empty()) {
    const std::string line = "slam_gmapping: ~" + problem +
                             " (set it with rosparam set /slam_gmapping/NAME VALUE, or _NAME:=VALUE)";
    ROS_FATAL("%s", line.c_str());
    throw std::invalid_argument(line);
  }
  pipeline_ = std::make_unique<ScanPipeline>(
      options, [this](const std::string& target, const std::string& source,
                      const ros::Time& stamp, geometry_msgs::TransformStamped* out,
                      std::string* error) {
        return waitForTransform(target, source, stamp, out, error);
      });

  odom_frame_ = pipeline_->odomFrame();
  base_frame_ = pipeline_->baseFrame();
  map_pub_ = node_.advertise<nav_msgs::OccupancyGrid>("map", 1, true);
  metadata_pub_ = node_.advertise<nav_msgs::MapMetaData>("map_metadata", 1, true);
  entropy_pub_ = private_.advertise<std_msgs::Float64>("entropy", 1, true);
  diagnostics_pub_ = node_.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10);
  map_service_ = node_.advertiseService("dynamic_map", &SlamGmappingNode::onMapRequest, this);
  scan_thread_ = std::thread([this] {
    while (auto scan = scans_.take()) processScan(*scan);
  });
  scan_sub_ = node_.subscribe("scan", 20, &SlamGmappingNode::onScan, this);
  // Beside tf's own listener: the odometry samples' stamps, each as it arrives.
  tf_sub_ = node_.subscribe("/tf", 100, &SlamGmappingNode::onTf, this);
  if (transform_publish_period_ > 0.0)
    tf_thread_ = std::thread([this] { publishTransformLoop(); });
  const SlamParams& params = pipeline_->params();
  ROS_INFO("slam_gmapping: waiting for scans on %s; frames %s -> %s -> %s -> <laser>; "
           "%d particles, linearUpdate %.2f m, angularUpdate %.2f rad, lskip %d",
           scan_sub_.getTopic().c_str(), map_frame_.c_str(), pipeline_->odomFrame().c_str(),
           pipeline_->baseFrame().c_str(), params.particles, params.linear_update,
           params.angular_update, params.matcher.lskip);
}

SlamGmappingNode::~SlamGmappingNode() {
  stopping_ = true;
  scans_.close();
  if (scan_thread_.joinable()) scan_thread_.join();
  if (tf_thread_.joinable()) tf_thread_.join();
}

// Once, at start-up: a private parameter the node does not read (a misspelt name, or one of
// gmapping's that gmapping_lite has no use for) would otherwise be ignored silently.
void SlamGmappingNode::warnUnusedParams() const {
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

bool SlamGmappingNode::waitForTransform(const std::string& target, const std::string& source,
                                        const ros::Time& stamp,
                                        geometry_msgs::TransformStamped* out,
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

// The subscriber's callback only hands the scan to the worker (processScan).
void SlamGmappingNode::onScan(const sensor_msgs::LaserScan::ConstPtr& scan) {
  const int received = ++scans_received_;
  if ((received - 1) % throttle_scans_ != 0) return;
  scans_.put(scan);
}

// Odometry's samples on /tf (odom_frame -> base_frame), for its period; roscpp does not run
// one subscription's callback concurrently, so odometry_period_ needs no lock.
void SlamGmappingNode::onTf(const tf2_msgs::TFMessage::ConstPtr& message) {
  bool seen = false;
  for (const auto& t : message->transforms) {
    if (stripSlash(t.header.frame_id) != odom_frame_ || stripSlash(t.child_frame_id) != base_frame_)
      continue;
    odometry_period_.add(t.header.stamp.toSec());
    seen = true;
  }
  if (seen) odometry_seconds_ = odometry_period_.period();
}

// At most one line every 30 wall seconds: a fast simulator runs many scan periods a second,
// and the count in each line says how it went since.
void SlamGmappingNode::warnSkipped() {
  const std::uint64_t skipped = scans_.skipped();
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
}

// A dropped scan, in the log: each reason throttled on its own (a log line per scan would
// flood it; malformed scans are throttled by scan time in the pipeline).
void SlamGmappingNode::logDrop(const ScanOutcome& outcome) {
  const char* problem = outcome.problem.c_str();
  switch (outcome.result) {
    case ScanResult::kUnstamped:
      ROS_WARN_THROTTLE(5.0, "slam_gmapping: %s", problem);
      break;
    case ScanResult::kMalformed:
      if (outcome.report) ROS_WARN("slam_gmapping: %s", problem);
      break;
    case ScanResult::kNoMount:
      ROS_WARN_THROTTLE(5.0, "slam_gmapping: %s Dropping scans until it appears.", problem);
      break;
    case ScanResult::kBadMount:
      ROS_ERROR_THROTTLE(5.0, "slam_gmapping: %s", problem);
      break;
    case ScanResult::kNoOdometry:
      ROS_WARN_THROTTLE(5.0, "slam_gmapping: %s", problem);
      break;
    case ScanResult::kUpdated:
    case ScanResult::kNotUpdated:
      break;
  }
}

void SlamGmappingNode::processScan(const sensor_msgs::LaserScan::ConstPtr& scan) {
  // The scan's number among those the mapper took (1 = the first): in the log, a gap
  // between two updates' numbers that is shorter than their time apart shows skipped scans.
  const int index = ++scans_taken_;
  warnSkipped();
  pipeline_->setOdometryPeriod(odometry_seconds_);
  const ScanOutcome outcome = pipeline_->process(*scan);
  for (const ScanNote& note : outcome.notes) {
    if (note.warning)
      ROS_WARN("slam_gmapping: %s", note.text.c_str());
    else
      ROS_INFO("slam_gmapping: %s", note.text.c_str());
  }
  if (!outcome.problem.empty()) {
    logDrop(outcome);
    return;
  }
  {
    std::lock_guard<std::mutex> lock(tf_mutex_);
    if (latest_stamp_ < scan->header.stamp) latest_stamp_ = scan->header.stamp;
  }
  if (outcome.result != ScanResult::kUpdated) return;

  const ParticleFilter& filter = *pipeline_->filter();
  const UpdateReport& report = outcome.update;
  {
    std::lock_guard<std::mutex> lock(tf_mutex_);
    map_to_odom_ = filter.mapToOdom();
    have_transform_ = true;
  }
  std_msgs::Float64 entropy;
  entropy.data = filter.entropy();
  entropy_pub_.publish(entropy);
  const std::string failed =
      report.failed_matches
          ? ", " + std::to_string(report.failed_matches) + " matches below minimumScore"
          : "";
  ROS_INFO("slam_gmapping: update %d (scan %d, t=%.2f): best pose (%.3f, %.3f, %.3f), "
           "Neff %.1f/%d%s, match score %.0f%s",
           report.update_index, index, scan->header.stamp.toSec(), report.best_pose.x,
           report.best_pose.y, report.best_pose.theta, report.neff,
           pipeline_->params().particles, report.resampled ? ", resampled" : "",
           report.best_score, failed.c_str());
  if (!have_map_ || (scan->header.stamp - last_map_update_).toSec() >= map_update_interval_) {
    publishMap(scan->header.stamp);
    publishDiagnostics(scan->header.stamp, report.update_index + 1);
    last_map_update_ = scan->header.stamp;
  }
}

// Scan counts on /diagnostics, with each map: WARN while scans are being skipped.
void SlamGmappingNode::publishDiagnostics(const ros::Time& stamp, int updates) {
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
  add("scans malformed", static_cast<std::uint64_t>(pipeline_->malformed()));
  add("scans without odometry", static_cast<std::uint64_t>(pipeline_->withoutOdometry()));
  add("updates", static_cast<std::uint64_t>(updates));
  diagnostic_msgs::DiagnosticArray array;
  array.header.stamp = stamp;
  array.status.push_back(status);
  diagnostics_pub_.publish(array);
}

void SlamGmappingNode::publishMap(const ros::Time& stamp) {
  const SlamParams& params = pipeline_->params();
  const OccupancyMap occ = toOccupancy(pipeline_->filter()->best().map, params.xmin,
                                       params.ymin, params.xmax, params.ymax, params.occ_thresh);
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
  ROS_INFO("slam_gmapping: published map %dx%d at %.3f m/cell, origin (%.2f, %.2f)", occ.width,
           occ.height, occ.resolution, occ.origin_x, occ.origin_y);
}

bool SlamGmappingNode::onMapRequest(nav_msgs::GetMap::Request&, nav_msgs::GetMap::Response& res) {
  std::lock_guard<std::mutex> lock(map_mutex_);
  if (!have_map_) return false;
  res.map = map_;
  return true;
}

void SlamGmappingNode::publishTransformLoop() {
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
      t.child_frame_id = pipeline_->odomFrame();
      broadcaster.sendTransform(t);
    }
    period.sleep();
  }
}

}  // namespace gmapping_lite
