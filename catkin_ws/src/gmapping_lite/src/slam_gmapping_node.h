// slam_gmapping: gmapping's ROS interface around the gmapping_lite particle filter.
//
// Subscribes `scan` and /tf (odometry's sample period, from the stamps of the odom_frame ->
// base_frame transforms: OdometryPeriod); reads odometry from tf (odom_frame -> base_frame at
// each scan's stamp) and the laser's mounting (base_frame -> scan frame, once per frame and
// beam layout).
// Publishes `map` and `map_metadata` (latched), `~entropy`, tf map_frame -> odom_frame,
// `/diagnostics` (scan counts, with each map), and serves `dynamic_map`.
//
// Scans are mapped by a worker thread that always takes the newest scan: when updates take
// longer than the scan period (a busy machine, a fast simulator) the scans it could not get
// to are skipped and counted, never queued up stale. What happens to each scan (checks, tf,
// the filter) is ScanPipeline's, shared with slam_offline; this class wires it to ROS.
#pragma once

#include <ros/ros.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/GetMap.h>
#include <nav_msgs/OccupancyGrid.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include "gmapping_lite/newest_slot.h"
#include "gmapping_lite/odometry_period.h"
#include "gmapping_lite/pose2.h"
#include "gmapping_lite/scan_pipeline.h"

namespace gmapping_lite {

class SlamGmappingNode {
 public:
  // Reads and checks the private parameters; throws std::invalid_argument with one line
  // naming the parameter when one cannot be used.
  SlamGmappingNode();
  ~SlamGmappingNode();

 private:
  void warnUnusedParams() const;
  // Wait (wall time, briefly) until tf can answer target <- source at `stamp`.
  bool waitForTransform(const std::string& target, const std::string& source,
                        const ros::Time& stamp, geometry_msgs::TransformStamped* out,
                        std::string* error);
  void onScan(const sensor_msgs::LaserScan::ConstPtr& scan);
  void onTf(const tf2_msgs::TFMessage::ConstPtr& message);
  void processScan(const sensor_msgs::LaserScan::ConstPtr& scan);
  void warnSkipped();
  void logDrop(const ScanOutcome& outcome);
  void publishDiagnostics(const ros::Time& stamp, int updates);
  void publishMap(const ros::Time& stamp);
  bool onMapRequest(nav_msgs::GetMap::Request&, nav_msgs::GetMap::Response& res);
  void publishTransformLoop();

  ros::NodeHandle node_, private_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  ros::Publisher map_pub_, metadata_pub_, entropy_pub_, diagnostics_pub_;
  ros::ServiceServer map_service_;
  ros::Subscriber scan_sub_, tf_sub_;

  std::string map_frame_;
  int throttle_scans_ = 1;
  double map_update_interval_ = 5.0, transform_publish_period_ = 0.05, tf_wait_ = 0.5;
  std::unique_ptr<ScanPipeline> pipeline_;  // used by the worker thread only
  std::string odom_frame_, base_frame_;     // as the pipeline has them (no leading '/')
  OdometryPeriod odometry_period_;          // by onTf only
  std::atomic<double> odometry_seconds_{0.0};  // its period, for the worker (0: unknown)
  std::atomic<int> scans_received_{0};
  NewestSlot<sensor_msgs::LaserScan::ConstPtr> scans_;
  int scans_taken_ = 0;  // by the worker thread only
  std::thread scan_thread_;
  std::uint64_t skipped_reported_ = 0, skipped_at_last_diagnostics_ = 0;
  ros::WallTime next_skip_warning_;

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
