// One scan's way from a LaserScan message to the particle filter, shared by the live node
// (slam_gmapping) and the bag processor (slam_offline): the stamp and layout checks, the
// laser's mounting from tf (cached per frame and beam layout), odometry from tf at the scan's
// stamp, the filter made at the first scan that can be placed (maxRange / maxUrange defaulted
// from its range_max), and the count of scans dropped for each reason.
//
// ROS message types only: no node handle, no clock, no logging. Each outcome carries the line
// to print, and the caller decides how (the node: ROS log, throttled; slam_offline: stderr).
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <geometry_msgs/TransformStamped.h>
#include <ros/time.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2/buffer_core.h>

#include "gmapping_lite/laser.h"
#include "gmapping_lite/particle_filter.h"
#include "gmapping_lite/scan_input.h"
#include "gmapping_lite/slam_params.h"

namespace gmapping_lite {

// The transform target <- source at `stamp` (ros::Time(0): the latest); false, with tf's
// reason in `error`, when tf cannot give it.
using TransformLookup =
    std::function<bool(const std::string& target, const std::string& source,
                       const ros::Time& stamp, geometry_msgs::TransformStamped* out,
                       std::string* error)>;

// A lookup that answers from `tf` at once, without waiting (a bag's tf, loaded beforehand).
TransformLookup lookupIn(const tf2::BufferCore& tf);

struct ScanPipelineOptions {
  std::string base_frame = "base_link", odom_frame = "odom";  // a leading '/' is ignored
  double tilt_tolerance = 0.1;  // rad: ~tilt_tolerance, see makeLaserGeometry
  SlamParams params;
  bool max_range_set = false, max_urange_set = false;  // else taken from the first scan
};

enum class ScanResult {
  kUpdated,      // the filter processed the scan (motion, match, resampling, map)
  kNotUpdated,   // placed, but the robot moved too little since the last update
  kUnstamped,    // stamped 0: dropped
  kMalformed,    // a layout no laser can have (scanProblem): dropped
  kNoMount,      // no base -> laser transform: dropped
  kBadMount,     // the laser's mounting cannot be used (tilted): dropped
  kNoOdometry,   // no odom -> base transform at the scan's stamp: dropped
};

struct ScanNote {
  bool warning = false;  // else information
  std::string text;
};

struct ScanOutcome {
  ScanResult result = ScanResult::kNotUpdated;
  // Why a scan was dropped, in one line (the frames, stamp and running count included);
  // empty for placed scans.
  std::string problem;
  // Malformed scans: false when the drop need not be said (ScanDrops's throttle by scan time).
  bool report = true;
  // Said once each: a laser placed or re-placed, its beam count changed, the filter made.
  std::vector<ScanNote> notes;
  UpdateReport update;  // for kUpdated and kNotUpdated
};

class ScanPipeline {
 public:
  // `lookup` answers both the laser's mounting and odometry; it may wait (the live node's
  // waits briefly for tf to catch up).
  ScanPipeline(const ScanPipelineOptions& options, TransformLookup lookup);

  ScanOutcome process(const sensor_msgs::LaserScan& scan);

  // Odometry's sample period (s; OdometryPeriod over the odom -> base transforms), given to
  // the filter with each scan from now on; 0 while unknown.
  void setOdometryPeriod(double seconds) { odometry_period_ = seconds; }

  // Null until the first scan that could be placed.
  const ParticleFilter* filter() const { return filter_.get(); }
  // The filter's parameters, with maxRange / maxUrange once the first scan set them.
  const SlamParams& params() const { return options_.params; }
  const std::string& baseFrame() const { return options_.base_frame; }
  const std::string& odomFrame() const { return options_.odom_frame; }

  int scans() const { return scans_; }  // every scan given to process()
  int unstamped() const { return unstamped_; }
  int malformed() const { return malformed_.total(); }
  int withoutMount() const { return without_mount_; }  // no mount, or one that cannot be used
  int withoutOdometry() const { return without_odometry_; }

 private:
  struct Laser {
    std::size_t count = 0;
    float angle_min = 0, angle_increment = 0;
    LaserGeometry geometry;
  };
  // The beams of `scan`'s laser in the base frame; null with outcome->problem set when the
  // laser cannot be placed.
  const LaserGeometry* laser(const sensor_msgs::LaserScan& scan, ScanOutcome* outcome);

  ScanPipelineOptions options_;
  TransformLookup lookup_;
  std::unique_ptr<ParticleFilter> filter_;
  std::map<std::string, Laser> lasers_;
  double odometry_period_ = 0.0;
  int scans_ = 0, unstamped_ = 0, without_mount_ = 0, without_odometry_ = 0;
  ScanDrops malformed_{5.0};  // say at most one drop every 5 s of scan time, with the count
};

// A frame name without tf1's leading '/'.
std::string stripSlash(const std::string& frame);

}  // namespace gmapping_lite
