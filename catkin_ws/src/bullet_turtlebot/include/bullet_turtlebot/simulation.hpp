// The simulated Turtlebot in its world, without ROS: commands in, a fixed physics step,
// true pose, drifting odometry, bumper state, sensor poses.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <random>

#include "bullet_turtlebot/diff_drive.hpp"
#include "bullet_turtlebot/odometry.hpp"
#include "bullet_turtlebot/sensors.hpp"
#include "bullet_turtlebot/world.hpp"

namespace bullet_turtlebot {

// Kobuki body and Turtlebot sensor mounts (base_footprint frame), from the URDF.
struct RobotGeometry {
  double radius = 0.18;
  double height = 0.40;
  double clearance = 0.02;  // obstacles lower than this pass under the robot
  Eigen::Vector3d depth_frame{-0.087, 0.0125, 0.0102 + 0.287};  // camera_depth_frame
  Eigen::Vector3d rgb_frame{-0.087, -0.0125, 0.0102 + 0.287};   // camera_rgb_frame
};

struct SimulationConfig {
  DriveLimits limits;
  RobotGeometry geometry;
  OdometryNoise odometry;
  double watchdog = 0.6;  // s without commands before the base stops
  double step = 0.01;     // physics step, s
  std::uint64_t seed = 1;
};

enum Bumper { kBumperLeft = 0, kBumperCenter = 1, kBumperRight = 2 };

struct BumperChange {
  int bumper;
  bool pressed;
};

// The free robot position nearest to `near` (searched on a 5 cm grid, rings of growing size,
// up to max_distance), or false when there is none.
bool find_free_position(const World& world, const RobotGeometry& geometry, const Eigen::Vector2d& near,
                        double max_distance, Eigen::Vector2d* found);

class Simulation {
 public:
  // Throws std::invalid_argument when the start pose is inside an obstacle.
  Simulation(std::shared_ptr<const World> world, const SimulationConfig& config, const Pose2D& start);

  // A validated command at time now(); (re)arms the watchdog.
  void command(double linear, double angular);
  // Moves the robot (at rest) to `pose`; false when the pose is inside an obstacle.
  bool teleport(const Pose2D& pose);
  // Advances one physics step; returns bumper changes during the step.
  std::vector<BumperChange> step();

  double now() const { return time_; }
  void set_time(double t) { time_ = t; }
  const Pose2D& pose() const { return pose_; }
  double linear_velocity() const { return v_; }
  double angular_velocity() const { return w_; }
  const OdometryModel& odometry() const { return odometry_; }
  const std::array<bool, 3>& bumpers() const { return bumpers_; }
  const World& world() const { return *world_; }
  const SimulationConfig& config() const { return config_; }
  SensorPose depth_sensor_pose() const { return sensor_pose(config_.geometry.depth_frame); }
  SensorPose rgb_sensor_pose() const { return sensor_pose(config_.geometry.rgb_frame); }
  std::mt19937_64& sensor_rng() { return sensor_rng_; }
  // Collisions so far (steps whose motion was cut short).
  std::uint64_t collisions() const { return collisions_; }

 private:
  SensorPose sensor_pose(const Eigen::Vector3d& mount) const;

  std::shared_ptr<const World> world_;
  SimulationConfig config_;
  Pose2D pose_;
  double v_ = 0.0, w_ = 0.0;
  double cmd_v_ = 0.0, cmd_w_ = 0.0;
  double last_command_ = -1e9;
  double time_ = 0.0;
  OdometryModel odometry_;
  std::mt19937_64 sensor_rng_;
  std::array<bool, 3> bumpers_{{false, false, false}};
  std::uint64_t collisions_ = 0;
};

}  // namespace bullet_turtlebot
