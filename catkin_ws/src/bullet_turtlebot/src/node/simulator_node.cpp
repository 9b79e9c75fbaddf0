// simulator: the Turtlebot simulator node (stands in for Gazebo and Stage).
#include <ros/ros.h>

#include <csignal>
#include <cstdio>
#include <memory>

#include "bullet_turtlebot/shipped_worlds.hpp"
#include "bullet_turtlebot/world_spec.hpp"
#include "ros_sim.hpp"

int main(int argc, char** argv) {
  // Our own SIGINT handler: roscpp's would shut the node down at once, and the simulator
  // still has to talk to the master on its way out (RosSimulator::restore_use_sim_time).
  ros::init(argc, argv, "simulator", ros::init_options::NoSigintHandler);
  std::signal(SIGINT, [](int) { bullet_turtlebot::RosSimulator::request_stop(); });
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  namespace bt = bullet_turtlebot;

  std::string world_name, worlds_dir;
  pnh.param<std::string>("world", world_name, "playground");
  pnh.param<std::string>("worlds_dir", worlds_dir, bt::shipped_worlds_dir());
  const std::string world_path = bt::resolve_world_path(world_name, worlds_dir);

  bt::WorldSpec spec;
  try {
    spec = bt::load_world_file(world_path);
  } catch (const bt::WorldFileError& e) {
    ROS_FATAL("%s", e.what());
    std::fprintf(stderr, "simulator: %s\n", e.what());
    return 2;
  }

  bt::SimulationConfig config;
  int seed = 1;
  pnh.param("seed", seed, seed);
  config.seed = static_cast<std::uint64_t>(seed);
  pnh.param("odom_noise", config.odometry.enabled, true);
  pnh.param("odom_linear_noise", config.odometry.linear, config.odometry.linear);
  pnh.param("odom_angular_noise", config.odometry.angular, config.odometry.angular);
  pnh.param("odom_angular_per_linear_noise", config.odometry.angular_per_linear, config.odometry.angular_per_linear);
  pnh.param("odom_yaw_scale_error", config.odometry.yaw_scale, config.odometry.yaw_scale);
  pnh.param("watchdog", config.watchdog, config.watchdog);
  pnh.param("max_linear", config.limits.max_linear, config.limits.max_linear);
  pnh.param("max_angular", config.limits.max_angular, config.limits.max_angular);
  pnh.param("accel_linear", config.limits.accel_linear, config.limits.accel_linear);
  pnh.param("accel_angular", config.limits.accel_angular, config.limits.accel_angular);
  double rate = 100.0;
  pnh.param("physics_rate", rate, rate);
  if (!(rate >= 10.0 && rate <= 10000.0)) {
    ROS_WARN("~physics_rate must lie in [10, 10000] Hz; using 100");
    rate = 100.0;
  }
  config.step = 1.0 / rate;

  bt::Pose2D start = spec.has_start ? spec.start : bt::Pose2D{};
  const bool chosen = spec.has_start || pnh.hasParam("x") || pnh.hasParam("y");
  pnh.param("x", start.x, start.x);
  pnh.param("y", start.y, start.y);
  pnh.param("yaw", start.yaw, start.yaw);

  try {
    auto world = std::make_shared<const bt::World>(spec);
    const bt::RobotGeometry& g = config.geometry;
    Eigen::Vector2d free;
    if (!chosen && world->cylinder_collides(Eigen::Vector2d(start.x, start.y), g.radius, g.height, g.clearance) &&
        bt::find_free_position(*world, g, Eigen::Vector2d(start.x, start.y), 20.0, &free)) {
      // Nobody asked for this pose: a world file without `start` whose origin is in a wall.
      ROS_WARN("world file '%s' gives no start pose and (%.2f, %.2f) is inside an obstacle: starting at the "
               "nearest free position (%.2f, %.2f); set x:= y:= or `start:` to choose",
               world_path.c_str(), start.x, start.y, free.x(), free.y());
      start.x = free.x();
      start.y = free.y();
    }
    bt::RosSimulator simulator(nh, pnh, world, config, start, world_path);
    const int status = simulator.run();
    ros::shutdown();
    return status;
  } catch (const std::invalid_argument& e) {
    ROS_FATAL("world file '%s': %s", world_path.c_str(), e.what());
    std::fprintf(stderr, "simulator: world file '%s': %s\n", world_path.c_str(), e.what());
    return 2;
  }
}
