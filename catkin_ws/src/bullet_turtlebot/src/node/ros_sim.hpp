// The thin ROS layer around bullet_turtlebot::Simulation: parameters, topics, tf, services
// and the paced main loop that publishes /clock.
#pragma once

#include <geometry_msgs/Pose2D.h>
#include <geometry_msgs/Twist.h>
#include <ros/ros.h>

#include <memory>
#include <random>
#include <string>

#include "bullet_turtlebot/command_mux.hpp"
#include "bullet_turtlebot/simulation.hpp"
#include "own_clock.hpp"

namespace bullet_turtlebot {

struct NodeRates {
  double odom = 50.0;
  double scan = 10.0;
  double camera = 10.0;
  double static_tf = 10.0;
};

class RosSimulator {
 public:
  RosSimulator(ros::NodeHandle nh, ros::NodeHandle pnh, std::shared_ptr<const World> world,
               const SimulationConfig& config, const Pose2D& start, const std::string& world_source);
  // Runs until shutdown or request_stop(); returns the process exit code.
  int run();
  // Ends run() at its next step; async-signal-safe (the node's SIGINT handler calls it).
  static void request_stop();

 private:
  void load_parameters();
  void advance();  // one physics step and everything due at its end
  void publish_clock();
  void publish_odometry();
  void publish_static_tf();
  void publish_scan();
  void publish_cameras();
  void on_velocity(const std::string& topic, int mux_input, const geometry_msgs::Twist& msg);
  void on_plain_cmd_vel();
  void on_set_pose(const geometry_msgs::Pose2D& msg);
  void restore_use_sim_time() const;  // on a clean exit: /use_sim_time as before the launch
  ros::Time stamp() const { return ros::Time(sim_.now()); }
  bool due(double rate) const;
  bool waiting_for_driver() const;  // ~wait_for_commands: hold the clock for a lagging driver
  static constexpr double kDriverQuietWallSeconds = 1.0;

  ros::NodeHandle nh_, pnh_;
  OwnClock own_clock_;  // after the node handles: it asks the master
  Simulation sim_;
  std::string world_source_;
  // ~use_sim_time_before_launch, set by simulator.launch: "unset", "true", "false" or
  // "other"; empty when the node was started without it (then it never touches the param).
  std::string use_sim_time_before_;
  CommandMux mux_;
  NodeRates rates_;
  LaserConfig laser_;
  CameraConfig camera_;
  double speed_ = 1.0;
  // Pacing by the driver (~wait_for_commands): sim seconds the clock may run ahead of the
  // newest velocity command (0: never waits), and when that command came.
  double command_lead_ = 0.0;
  double last_command_sim_ = -1.0;
  ros::WallTime last_command_wall_;
  double huge_linear_ = 10.0, huge_angular_ = 20.0;
  bool publish_static_tf_ = true;
  bool paused_ = false;
  std::uint64_t steps_ = 0;
  ros::WallTime last_cmd_vel_warning_;
  // Throttled per reason, so a flood of one kind of bad command cannot hide another kind.
  ros::WallTime last_nonfinite_warning_, last_too_large_warning_;

  ros::Publisher clock_pub_, odom_pub_, truth_pub_, tf_pub_, scan_pub_, bumper_pub_;
  ros::Publisher depth_pub_, depth_info_pub_, points_pub_, rgb_pub_, rgb_info_pub_;
  std::vector<ros::Subscriber> subscribers_;
  std::vector<ros::ServiceServer> services_;
};

}  // namespace bullet_turtlebot
