#include "ros_sim.hpp"
#include "batch_scheduling.hpp"
#include "checked_params.hpp"

#include <bullet_turtlebot/BumperEvent.h>
#include <nav_msgs/Odometry.h>
#include <ros/master.h>
#include <ros/this_node.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/PointCloud2.h>
#include <sensor_msgs/PointField.h>
#include <std_srvs/Empty.h>
#include <std_srvs/Trigger.h>
#include <tf2_msgs/TFMessage.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>

namespace bullet_turtlebot {
namespace {

volatile std::sig_atomic_t g_stop_requested = 0;

geometry_msgs::Quaternion yaw_quaternion(double yaw) {
  geometry_msgs::Quaternion q;
  q.z = std::sin(yaw / 2);
  q.w = std::cos(yaw / 2);
  return q;
}

geometry_msgs::TransformStamped transform(const ros::Time& stamp, const std::string& parent,
                                          const std::string& child, double x, double y, double z,
                                          const geometry_msgs::Quaternion& q) {
  geometry_msgs::TransformStamped t;
  t.header.stamp = stamp;
  t.header.frame_id = parent;
  t.child_frame_id = child;
  t.transform.translation.x = x;
  t.transform.translation.y = y;
  t.transform.translation.z = z;
  t.transform.rotation = q;
  return t;
}

// The base's planar pose in `frame` and its body-frame velocity; covariances left to the caller.
nav_msgs::Odometry odometry_message(const ros::Time& stamp, const std::string& frame, const Pose2D& pose,
                                    double linear_velocity, double angular_velocity) {
  nav_msgs::Odometry msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = frame;
  msg.child_frame_id = "base_footprint";
  msg.pose.pose.position.x = pose.x;
  msg.pose.pose.position.y = pose.y;
  msg.pose.pose.orientation = yaw_quaternion(pose.yaw);
  msg.twist.twist.linear.x = linear_velocity;
  msg.twist.twist.angular.z = angular_velocity;
  return msg;
}

sensor_msgs::CameraInfo camera_info(const CameraConfig& camera, const std::string& frame, const ros::Time& stamp) {
  sensor_msgs::CameraInfo info;
  info.header.stamp = stamp;
  info.header.frame_id = frame;
  info.width = static_cast<uint32_t>(camera.width);
  info.height = static_cast<uint32_t>(camera.height);
  info.distortion_model = "plumb_bob";
  info.D.assign(5, 0.0);
  const double f = camera.focal();
  info.K = {f, 0, camera.cx(), 0, f, camera.cy(), 0, 0, 1};
  info.R = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  info.P = {f, 0, camera.cx(), 0, 0, f, camera.cy(), 0, 0, 0, 1, 0};
  return info;
}

// An Image of the camera's size with everything but the pixels (little-endian rows of
// `bytes_per_pixel` each).
sensor_msgs::Image image_header(const CameraConfig& camera, const std::string& frame, const ros::Time& stamp,
                                const std::string& encoding, uint32_t bytes_per_pixel) {
  sensor_msgs::Image image;
  image.header.stamp = stamp;
  image.header.frame_id = frame;
  image.width = static_cast<uint32_t>(camera.width);
  image.height = static_cast<uint32_t>(camera.height);
  image.encoding = encoding;
  image.is_bigendian = 0;
  image.step = image.width * bytes_per_pixel;
  return image;
}

template <typename T>
T param(const ros::NodeHandle& pnh, const std::string& name, T fallback) {
  T value;
  pnh.param(name, value, fallback);
  return value;
}

}  // namespace

RosSimulator::RosSimulator(ros::NodeHandle nh, ros::NodeHandle pnh, std::shared_ptr<const World> world,
                           const SimulationConfig& config, const Pose2D& start, const std::string& world_source)
    : nh_(nh), pnh_(pnh), sim_(std::move(world), config, start), world_source_(world_source),
      mux_(turtlebot_mux_inputs()) {
  load_parameters();
  own_clock_.set(stamp());  // the start time, before anything logs
  clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 10);
  odom_pub_ = nh_.advertise<nav_msgs::Odometry>("odom", 20);
  truth_pub_ = nh_.advertise<nav_msgs::Odometry>("base_pose_ground_truth", 20);
  tf_pub_ = nh_.advertise<tf2_msgs::TFMessage>("/tf", 100);
  scan_pub_ = nh_.advertise<sensor_msgs::LaserScan>("scan", 10);
  bumper_pub_ = nh_.advertise<BumperEvent>("mobile_base/events/bumper", 10);
  depth_pub_ = nh_.advertise<sensor_msgs::Image>("camera/depth/image_raw", 2);
  depth_info_pub_ = nh_.advertise<sensor_msgs::CameraInfo>("camera/depth/camera_info", 2);
  points_pub_ = nh_.advertise<sensor_msgs::PointCloud2>("camera/depth/points", 2);
  rgb_pub_ = nh_.advertise<sensor_msgs::Image>("camera/rgb/image_raw", 2);
  rgb_info_pub_ = nh_.advertise<sensor_msgs::CameraInfo>("camera/rgb/camera_info", 2);

  subscribers_.push_back(nh_.subscribe<geometry_msgs::Twist>(
      "mobile_base/commands/velocity", 10,
      [this](const geometry_msgs::TwistConstPtr& msg) { on_velocity("mobile_base/commands/velocity", -1, *msg); }));
  const auto& inputs = mux_.inputs();
  for (size_t i = 0; i < inputs.size(); ++i) {
    const std::string topic = "cmd_vel_mux/input/" + inputs[i].name;
    subscribers_.push_back(nh_.subscribe<geometry_msgs::Twist>(
        topic, 10, [this, topic, i](const geometry_msgs::TwistConstPtr& msg) {
          on_velocity(topic, static_cast<int>(i), *msg);
        }));
  }
  subscribers_.push_back(
      nh_.subscribe<geometry_msgs::Twist>("cmd_vel", 1, [this](const geometry_msgs::TwistConstPtr&) { on_plain_cmd_vel(); }));
  subscribers_.push_back(pnh_.subscribe<geometry_msgs::Pose2D>(
      "set_pose", 1, [this](const geometry_msgs::Pose2DConstPtr& msg) { on_set_pose(*msg); }));

  services_.push_back(pnh_.advertiseService<std_srvs::Empty::Request, std_srvs::Empty::Response>(
      "pause", [this](std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
        paused_ = true;
        return true;
      }));
  services_.push_back(pnh_.advertiseService<std_srvs::Empty::Request, std_srvs::Empty::Response>(
      "unpause", [this](std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
        paused_ = false;
        return true;
      }));
  services_.push_back(pnh_.advertiseService<std_srvs::Trigger::Request, std_srvs::Trigger::Response>(
      "step", [this](std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
        if (!paused_) {
          res.success = false;
          res.message = "not paused: call ~pause first";
          return true;
        }
        advance();
        res.success = true;
        res.message = "time " + std::to_string(sim_.now());
        return true;
      }));
}

void RosSimulator::load_parameters() {
  constexpr double kHuge = 1e6;
  speed_ = checked_number(pnh_, "speed", 1.0, 0.0, kHuge,
                          "0 (as fast as possible) or more sim seconds per wall second");
  command_lead_ = checked_number(pnh_, "wait_for_commands", 0.0, 0.0, kHuge, "0 (off) or more sim seconds");
  paused_ = param(pnh_, "start_paused", false);
  // ROS time holds unsigned 32-bit seconds; /clock must never read 0.
  sim_.set_time(checked_number(pnh_, "start_time", 1.0, above(0.0), 4.0e9, "a sim time in (0, 4e9] s"));
  // A rate above the physics rate would claim samples the simulation never takes.
  const double physics_rate = 1.0 / sim_.config().step;
  const std::string rate_rule = "0 (off) up to the physics rate, " + std::to_string(physics_rate) + " Hz";
  rates_.odom = checked_number(pnh_, "odom_rate", rates_.odom, 0.0, physics_rate, rate_rule);
  rates_.scan = checked_number(pnh_, "scan_rate", rates_.scan, 0.0, physics_rate, rate_rule);
  rates_.camera = checked_number(pnh_, "camera_rate", rates_.camera, 0.0, physics_rate, rate_rule);
  rates_.static_tf = checked_number(pnh_, "static_tf_rate", rates_.static_tf, 0.0, physics_rate, rate_rule);
  publish_static_tf_ = param(pnh_, "publish_static_tf", true);
  laser_.samples = checked_int(pnh_, "scan_samples", laser_.samples, 1, 100000, "a beam count in [1, 100000]");
  laser_.fov = checked_number(pnh_, "scan_fov_deg", 58.0, above(0.0), 360.0, "degrees in (0, 360]") * M_PI / 180.0;
  laser_.range_max =
      checked_number(pnh_, "range_max", laser_.range_max, above(0.0), 1000.0, "metres in (0, 1000]");
  laser_.range_min = checked_number(pnh_, "range_min", std::min(laser_.range_min, laser_.range_max / 2), 0.0,
                                    std::nextafter(laser_.range_max, 0.0), "metres in [0, range_max)");
  const bool sensor_noise = param(pnh_, "sensor_noise", true);
  const std::string noise_rule = "a standard deviation in [0, 1]";
  laser_.noise = sensor_noise ? checked_number(pnh_, "range_noise", 0.003, 0.0, 1.0, noise_rule) : 0.0;
  laser_.noise_quadratic =
      sensor_noise ? checked_number(pnh_, "range_noise_quadratic", 0.0019, 0.0, 1.0, noise_rule) : 0.0;
  // 2048 x 2048 bounds the depth and colour buffers at about 30 MB (the Kinect is 640 x 480).
  const std::string size_rule = "pixels in [2, 2048]";
  camera_.width = checked_int(pnh_, "camera_width", camera_.width, 2, 2048, size_rule);
  camera_.height = checked_int(pnh_, "camera_height", camera_.height, 2, 2048, size_rule);
  camera_.hfov = laser_.fov;
  camera_.depth_min = laser_.range_min;
  huge_linear_ = checked_number(pnh_, "huge_linear", huge_linear_, above(0.0), kHuge, "m/s above 0");
  huge_angular_ = checked_number(pnh_, "huge_angular", huge_angular_, above(0.0), kHuge, "rad/s above 0");
  use_sim_time_before_ = param(pnh_, "use_sim_time_before_launch", std::string());
}

void RosSimulator::request_stop() { g_stop_requested = 1; }

// simulator.launch sets /use_sim_time true for every node it starts, and roslaunch leaves it
// on the master when the launch ends: on a long-lived roscore, later nodes would then wait
// for a /clock nobody publishes. The launch file records the value from before it (see
// there); put that back, unless someone changed the parameter since.
void RosSimulator::restore_use_sim_time() const {
  if (use_sim_time_before_.empty() || use_sim_time_before_ == "true" || use_sim_time_before_ == "other") return;
  XmlRpc::XmlRpcValue request, response, value;
  request[0] = ros::this_node::getName();
  request[1] = std::string("/use_sim_time");
  // wait_for_master false throughout: if the master has gone, there is nothing to restore.
  if (!ros::master::execute("getParam", request, response, value, false)) return;
  if (value.getType() != XmlRpc::XmlRpcValue::TypeBoolean || !static_cast<bool>(value)) return;
  XmlRpc::XmlRpcValue ignored;
  if (use_sim_time_before_ == "unset") {
    if (ros::master::execute("deleteParam", request, response, ignored, false))
      ROS_INFO("simulator: removed /use_sim_time (it was not set before the launch)");
  } else {
    request[2] = false;
    if (ros::master::execute("setParam", request, response, ignored, false))
      ROS_INFO("simulator: /use_sim_time back to false (as before the launch)");
  }
}

bool RosSimulator::due(double rate) const {
  if (!(rate > 0)) return false;
  const std::uint64_t period = std::max<std::uint64_t>(1, std::llround(1.0 / (rate * sim_.config().step)));
  return steps_ % period == 0;
}

void RosSimulator::on_plain_cmd_vel() {
  const ros::WallTime now = ros::WallTime::now();
  if ((now - last_cmd_vel_warning_).toSec() < 5.0) return;
  last_cmd_vel_warning_ = now;
  ROS_WARN("Ignoring a velocity command on %s: the Turtlebot listens on cmd_vel_mux/input/teleop. "
           "Remap your node's topic: cmd_vel:=cmd_vel_mux/input/teleop",
           ros::names::resolve("cmd_vel").c_str());
}

void RosSimulator::on_velocity(const std::string& topic, int mux_input, const geometry_msgs::Twist& msg) {
  const double linear[3] = {msg.linear.x, msg.linear.y, msg.linear.z};
  const double angular[3] = {msg.angular.x, msg.angular.y, msg.angular.z};
  const CommandCheck check = check_command(linear, angular, huge_linear_, huge_angular_);
  if (check != CommandCheck::kOk) {
    const ros::WallTime now = ros::WallTime::now();
    ros::WallTime& last_warning =
        check == CommandCheck::kNotFinite ? last_nonfinite_warning_ : last_too_large_warning_;
    if ((now - last_warning).toSec() >= 1.0) {
      last_warning = now;
      ROS_WARN("Rejected velocity command on %s (linear.x=%g angular.z=%g): %s; the base keeps its current command",
               topic.c_str(), msg.linear.x, msg.angular.z,
               check == CommandCheck::kNotFinite
                   ? "NaN or infinite component"
                   : ("beyond the plausible limits |linear| <= " + std::to_string(huge_linear_) +
                      " m/s, |angular| <= " + std::to_string(huge_angular_) + " rad/s")
                         .c_str());
    }
    return;
  }
  last_command_sim_ = sim_.now();
  last_command_wall_ = ros::WallTime::now();
  if (mux_input >= 0 && !mux_.offer(mux_input, sim_.now())) return;  // a higher priority input owns the base
  sim_.command(msg.linear.x, msg.angular.z);
}

void RosSimulator::on_set_pose(const geometry_msgs::Pose2D& msg) {
  if (!std::isfinite(msg.x) || !std::isfinite(msg.y) || !std::isfinite(msg.theta)) {
    ROS_WARN("~set_pose: ignoring a non-finite pose");
    return;
  }
  // The ~x / ~y rule: Bullet's single precision cannot place the robot farther than 1e6 m.
  if (std::abs(msg.x) > 1e6 || std::abs(msg.y) > 1e6 || std::abs(msg.theta) > 1e3) {
    ROS_WARN("~set_pose: ignoring (%g, %g, %g): x and y must be metres within 1e6 of the origin, "
             "theta radians within 1000",
             msg.x, msg.y, msg.theta);
    return;
  }
  if (!sim_.teleport(Pose2D{msg.x, msg.y, msg.theta})) {
    ROS_WARN("~set_pose: (%g, %g) is inside an obstacle; the robot stays where it is", msg.x, msg.y);
  }
}

void RosSimulator::publish_clock() {
  rosgraph_msgs::Clock clock;
  clock.clock = stamp();
  own_clock_.set(clock.clock);
  clock_pub_.publish(clock);
}

void RosSimulator::publish_odometry() {
  const ros::Time now = stamp();
  const OdometryModel& odom = sim_.odometry();
  nav_msgs::Odometry msg =
      odometry_message(now, "odom", odom.pose(), odom.linear_velocity(), odom.angular_velocity());
  // Variances that grow with the distance and angle travelled, as the drift model does.
  const OdometryNoise& n = odom.noise();
  const double var_xy = n.enabled ? 1e-4 + n.linear * n.linear * odom.travelled() : 1e-6;
  const double var_yaw = n.enabled ? 1e-4 + n.angular * n.angular * odom.turned() +
                                         n.angular_per_linear * n.angular_per_linear * odom.travelled()
                                   : 1e-6;
  msg.pose.covariance[0] = var_xy;
  msg.pose.covariance[7] = var_xy;
  msg.pose.covariance[14] = 1e6;  // z, roll, pitch: not estimated
  msg.pose.covariance[21] = 1e6;
  msg.pose.covariance[28] = 1e6;
  msg.pose.covariance[35] = var_yaw;
  msg.twist.covariance[0] = 1e-3;
  msg.twist.covariance[7] = 1e-3;
  msg.twist.covariance[14] = 1e6;
  msg.twist.covariance[21] = 1e6;
  msg.twist.covariance[28] = 1e6;
  msg.twist.covariance[35] = 1e-3;
  odom_pub_.publish(msg);

  tf2_msgs::TFMessage tf;
  tf.transforms.push_back(transform(now, "odom", "base_footprint", odom.pose().x, odom.pose().y, 0.0,
                                    msg.pose.pose.orientation));
  tf_pub_.publish(tf);

  truth_pub_.publish(
      odometry_message(now, "world", sim_.pose(), sim_.linear_velocity(), sim_.angular_velocity()));
}

void RosSimulator::publish_static_tf() {
  // The URDF's fixed chain down to the scan frame, also on /tf, so that
  // `rosbag record /scan /tf` alone holds every transform SLAM needs.
  const ros::Time now = stamp();
  const RobotGeometry& g = sim_.config().geometry;
  const geometry_msgs::Quaternion identity = yaw_quaternion(0.0);
  const double base_z = 0.0102;
  tf2_msgs::TFMessage tf;
  tf.transforms.push_back(transform(now, "base_footprint", "base_link", 0, 0, base_z, identity));
  tf.transforms.push_back(transform(now, "base_link", "camera_rgb_frame", g.rgb_frame.x(), g.rgb_frame.y(),
                                    g.rgb_frame.z() - base_z, identity));
  tf.transforms.push_back(transform(now, "camera_rgb_frame", "camera_depth_frame", g.depth_frame.x() - g.rgb_frame.x(),
                                    g.depth_frame.y() - g.rgb_frame.y(), g.depth_frame.z() - g.rgb_frame.z(),
                                    identity));
  tf_pub_.publish(tf);
}

void RosSimulator::publish_scan() {
  sensor_msgs::LaserScan scan;
  scan.header.stamp = stamp();
  scan.header.frame_id = "camera_depth_frame";
  scan.angle_min = static_cast<float>(laser_.angle_min());
  scan.angle_max = static_cast<float>(-laser_.angle_min());
  scan.angle_increment = static_cast<float>(laser_.angle_increment());
  scan.time_increment = 0.0f;
  scan.scan_time = static_cast<float>(1.0 / rates_.scan);
  scan.range_min = static_cast<float>(laser_.range_min);
  scan.range_max = static_cast<float>(laser_.range_max);
  scan_ranges(sim_.world(), laser_, sim_.depth_sensor_pose(), &sim_.sensor_rng(), &scan.ranges);
  scan_pub_.publish(scan);
}

void RosSimulator::publish_cameras() {
  const ros::Time now = stamp();
  if (depth_info_pub_.getNumSubscribers() > 0) {
    depth_info_pub_.publish(camera_info(camera_, "camera_depth_optical_frame", now));
  }
  if (rgb_info_pub_.getNumSubscribers() > 0) {
    rgb_info_pub_.publish(camera_info(camera_, "camera_rgb_optical_frame", now));
  }
  const bool want_depth = depth_pub_.getNumSubscribers() > 0;
  const bool want_points = points_pub_.getNumSubscribers() > 0;
  if (want_depth || want_points) {
    std::vector<float> depth;
    render_depth(sim_.world(), camera_, sim_.depth_sensor_pose(), &depth);
    if (want_depth) {
      sensor_msgs::Image image = image_header(camera_, "camera_depth_optical_frame", now, "32FC1", 4);
      image.data.resize(depth.size() * 4);
      std::memcpy(image.data.data(), depth.data(), image.data.size());
      depth_pub_.publish(image);
    }
    if (want_points) {
      sensor_msgs::PointCloud2 cloud;
      cloud.header.stamp = now;
      cloud.header.frame_id = "camera_depth_optical_frame";
      cloud.width = static_cast<uint32_t>(camera_.width);
      cloud.height = static_cast<uint32_t>(camera_.height);
      cloud.is_bigendian = false;
      cloud.is_dense = false;  // NaN where nothing was seen
      cloud.point_step = 12;
      cloud.row_step = cloud.point_step * cloud.width;
      for (const char* name : {"x", "y", "z"}) {
        sensor_msgs::PointField field;
        field.name = name;
        field.offset = static_cast<uint32_t>(cloud.fields.size() * 4);
        field.datatype = sensor_msgs::PointField::FLOAT32;
        field.count = 1;
        cloud.fields.push_back(field);
      }
      cloud.data.resize(depth.size() * 12);
      const double f = camera_.focal();
      float* out = reinterpret_cast<float*>(cloud.data.data());
      size_t k = 0;
      for (int v = 0; v < camera_.height; ++v) {
        for (int u = 0; u < camera_.width; ++u, ++k) {
          const float z = depth[k];
          out[3 * k] = static_cast<float>((u - camera_.cx()) / f) * z;
          out[3 * k + 1] = static_cast<float>((v - camera_.cy()) / f) * z;
          out[3 * k + 2] = z;
        }
      }
      points_pub_.publish(cloud);
    }
  }
  if (rgb_pub_.getNumSubscribers() > 0) {
    sensor_msgs::Image image = image_header(camera_, "camera_rgb_optical_frame", now, "rgb8", 3);
    render_rgb(sim_.world(), camera_, sim_.rgb_sensor_pose(), &image.data);
    rgb_pub_.publish(image);
  }
}

void RosSimulator::advance() {
  for (const BumperChange& change : sim_.step()) {
    BumperEvent event;
    event.bumper = static_cast<uint8_t>(change.bumper);
    event.state = change.pressed ? BumperEvent::PRESSED : BumperEvent::RELEASED;
    bumper_pub_.publish(event);
  }
  ++steps_;
  publish_clock();
  if (due(rates_.odom)) publish_odometry();
  if (publish_static_tf_ && due(rates_.static_tf)) publish_static_tf();
  if (due(rates_.scan)) publish_scan();
  if (due(rates_.camera)) publish_cameras();
}

// With ~wait_for_commands, a driver that lags (a loaded machine, a slow planner) holds the
// clock instead of watching the base stop under it: the clock stays within the lead of its
// newest command. A driver that goes quiet for a wall second on purpose no longer holds it.
bool RosSimulator::waiting_for_driver() const {
  if (!(command_lead_ > 0) || last_command_sim_ < 0) return false;
  if (sim_.now() - last_command_sim_ < command_lead_) return false;
  return (ros::WallTime::now() - last_command_wall_).toSec() < kDriverQuietWallSeconds;
}

int RosSimulator::run() {
  ROS_INFO("simulator: world %s, %zu solids, robot at (%.2f, %.2f, %.2f), speed %g%s", world_source_.c_str(),
           sim_.world().solids().size(), sim_.pose().x, sim_.pose().y, sim_.pose().yaw, speed_,
           speed_ == 0 ? " (as fast as possible)" : "");
  if (speed_ == 0 && !use_batch_scheduling()) {
    ROS_WARN("simulator: SCHED_BATCH refused; running with the default scheduling");
  }
  // Publish the first clock tick and state before any step, so nothing sees time 0.
  publish_clock();
  publish_odometry();
  if (publish_static_tf_) publish_static_tf();
  ros::WallTime anchor_wall = ros::WallTime::now();
  double anchor_sim = sim_.now();
  const ros::WallTime run_start = anchor_wall;
  const double sim_start = sim_.now();
  ros::WallTime last_paused_clock;
  while (ros::ok() && !g_stop_requested) {
    ros::spinOnce();
    if (paused_) {
      // Keep repeating the (frozen) time so nodes started meanwhile learn it.
      const ros::WallTime now = ros::WallTime::now();
      if ((now - last_paused_clock).toSec() >= 0.1) {
        publish_clock();
        last_paused_clock = now;
      }
      ros::WallDuration(0.002).sleep();
      anchor_wall = ros::WallTime::now();
      anchor_sim = sim_.now();
      continue;
    }
    if (waiting_for_driver()) {
      ros::WallDuration(0.001).sleep();
      anchor_wall = ros::WallTime::now();  // a wait is not lag to make up afterwards
      anchor_sim = sim_.now();
      continue;
    }
    advance();
    if (speed_ > 0) {
      const ros::WallTime target = anchor_wall + ros::WallDuration((sim_.now() - anchor_sim) / speed_);
      const ros::WallTime now = ros::WallTime::now();
      if (target > now) {
        (target - now).sleep();
      } else if ((now - target).toSec() > 0.5) {
        anchor_wall = now;  // fell behind (slow machine): do not race to catch up
        anchor_sim = sim_.now();
      }
    }
  }
  // A clean exit (SIGINT, as roslaunch sends it) leaves the node connected: tidy up the master.
  if (ros::ok()) restore_use_sim_time();
  const double wall = (ros::WallTime::now() - run_start).toSec();
  // Plain stdout: rosout may be gone by now. Benchmarks parse this line.
  std::printf("simulator: simulated %.2f s in %.2f wall s (real-time factor %.1f), %llu collision steps\n",
              sim_.now() - sim_start, wall, wall > 0 ? (sim_.now() - sim_start) / wall : 0.0,
              static_cast<unsigned long long>(sim_.collisions()));
  std::fflush(stdout);
  return 0;
}

}  // namespace bullet_turtlebot
