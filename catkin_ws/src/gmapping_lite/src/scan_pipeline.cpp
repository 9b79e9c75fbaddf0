#include "gmapping_lite/scan_pipeline.h"

#include <cstdarg>
#include <cstdio>
#include <utility>

#include <tf2/exceptions.h>
#include <tf2/utils.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include "gmapping_lite/param_table.h"

namespace gmapping_lite {

namespace {

std::string format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
std::string format(const char* fmt, ...) {
  va_list args;
  va_start(args, fmt);
  va_list again;
  va_copy(again, args);
  const int size = std::vsnprintf(nullptr, 0, fmt, args);
  va_end(args);
  std::string out(size > 0 ? std::size_t(size) : 0, '\0');
  if (size > 0) std::vsnprintf(out.data(), out.size() + 1, fmt, again);
  va_end(again);
  return out;
}

}  // namespace

std::string stripSlash(const std::string& frame) {
  return !frame.empty() && frame[0] == '/' ? frame.substr(1) : frame;
}

TransformLookup lookupIn(const tf2::BufferCore& tf) {
  return [&tf](const std::string& target, const std::string& source, const ros::Time& stamp,
               geometry_msgs::TransformStamped* out, std::string* error) {
    try {
      *out = tf.lookupTransform(target, source, stamp);
      return true;
    } catch (const tf2::TransformException& e) {
      *error = e.what();
      return false;
    }
  };
}

ScanPipeline::ScanPipeline(const ScanPipelineOptions& options, TransformLookup lookup)
    : options_(options), lookup_(std::move(lookup)) {
  options_.base_frame = stripSlash(options_.base_frame);
  options_.odom_frame = stripSlash(options_.odom_frame);
}

const LaserGeometry* ScanPipeline::laser(const sensor_msgs::LaserScan& scan,
                                         ScanOutcome* outcome) {
  const std::string frame = stripSlash(scan.header.frame_id);
  const auto it = lasers_.find(frame);
  const bool known = it != lasers_.end();
  if (known && it->second.count == scan.ranges.size() &&
      it->second.angle_min == scan.angle_min &&
      it->second.angle_increment == scan.angle_increment)
    return &it->second.geometry;
  if (known && it->second.count != scan.ranges.size())
    outcome->notes.push_back(
        {true, format("the scan on frame %s changed from %zu to %zu beams; rebuilding the "
                      "beam table and carrying on",
                      frame.c_str(), it->second.count, scan.ranges.size())});
  geometry_msgs::TransformStamped mount;
  std::string error;
  // The mounting is static: the latest transform will do.
  if (!lookup_(options_.base_frame, frame, ros::Time(0), &mount, &error)) {
    ++without_mount_;
    outcome->result = ScanResult::kNoMount;
    outcome->problem = format("cannot place the laser: no transform from base frame '%s' to "
                              "laser frame '%s' (%s). Is robot_state_publisher or a static "
                              "transform publisher running?",
                              options_.base_frame.c_str(), frame.c_str(), error.c_str());
    return nullptr;
  }
  tf2::Transform laser_in_base;
  tf2::fromMsg(mount.transform, laser_in_base);
  Laser entry;
  entry.count = scan.ranges.size();
  entry.angle_min = scan.angle_min;
  entry.angle_increment = scan.angle_increment;
  if (!makeLaserGeometry(laser_in_base, scan.angle_min, scan.angle_increment, scan.ranges.size(),
                         options_.tilt_tolerance, &entry.geometry, &error)) {
    ++without_mount_;
    outcome->result = ScanResult::kBadMount;
    outcome->problem = format("laser frame '%s': %s", frame.c_str(), error.c_str());
    return nullptr;
  }
  outcome->notes.push_back(
      {false, format("laser '%s' at (%.3f, %.3f) in '%s', %zu beams from %.3f to %.3f rad%s",
                     frame.c_str(), entry.geometry.origin.x, entry.geometry.origin.y,
                     options_.base_frame.c_str(), entry.count, scan.angle_min,
                     scan.angle_min + scan.angle_increment * (double(entry.count) - 1),
                     upsideDown(laser_in_base) ? " (mounted upside down: beam angles mirrored)"
                                               : "")});
  Laser& stored = lasers_[frame];
  stored = std::move(entry);
  return &stored.geometry;
}

ScanOutcome ScanPipeline::process(const sensor_msgs::LaserScan& scan) {
  ++scans_;
  ScanOutcome outcome;
  const double stamp = scan.header.stamp.toSec();
  if (scan.header.stamp.isZero()) {
    // tf would answer a lookup at time 0 with its latest transform: the wrong odometry.
    ++unstamped_;
    outcome.result = ScanResult::kUnstamped;
    outcome.problem = "ignoring a scan stamped 0 (is the publisher waiting for /clock?)";
    return outcome;
  }
  if (const auto problem = scanProblem(scan.angle_min, scan.angle_max, scan.angle_increment,
                                       scan.ranges.size(), scan.range_min, scan.range_max)) {
    outcome.result = ScanResult::kMalformed;
    outcome.report = malformed_.count(stamp);
    outcome.problem = format("dropping a malformed scan on frame '%s' at %.3f: %s; malformed "
                             "scans dropped so far: %d",
                             scan.header.frame_id.c_str(), stamp, problem->c_str(),
                             malformed_.total());
    return outcome;
  }
  const LaserGeometry* geometry = laser(scan, &outcome);
  if (!geometry) return outcome;
  geometry_msgs::TransformStamped odom_tf;
  std::string error;
  if (!lookup_(options_.odom_frame, options_.base_frame, scan.header.stamp, &odom_tf, &error)) {
    ++without_odometry_;
    outcome.result = ScanResult::kNoOdometry;
    outcome.problem = format("no odometry: transform from '%s' to '%s' at the scan's stamp %.3f "
                             "is not available (%s); %d scans dropped so far",
                             options_.odom_frame.c_str(), options_.base_frame.c_str(), stamp,
                             error.c_str(), without_odometry_);
    return outcome;
  }
  if (!filter_) {
    const std::string note = rangeDefaults(&options_.params, scan.range_max,
                                           options_.max_range_set, options_.max_urange_set);
    if (!note.empty()) outcome.notes.push_back({true, note});
    filter_ = std::make_unique<ParticleFilter>(options_.params);
    outcome.notes.push_back({false, format("maxRange %.2f m, maxUrange %.2f m",
                                           options_.params.matcher.max_range,
                                           options_.params.matcher.max_urange)});
  }
  const Pose2 odom(odom_tf.transform.translation.x, odom_tf.transform.translation.y,
                   tf2::getYaw(odom_tf.transform.rotation));
  filter_->setOdometryPeriod(odometry_period_);
  outcome.update = filter_->addScan(odom, stamp, *geometry,
                                    toRanges(scan.ranges, scan.range_min, scan.range_max));
  outcome.result = outcome.update.processed ? ScanResult::kUpdated : ScanResult::kNotUpdated;
  return outcome;
}

}  // namespace gmapping_lite
