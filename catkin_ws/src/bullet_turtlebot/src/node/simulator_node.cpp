// simulator: the Turtlebot simulator node (stands in for Gazebo and Stage).
#include <ros/ros.h>
#include <rosbook_env/master_watch.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "bullet_turtlebot/shipped_worlds.hpp"
#include "bullet_turtlebot/world_spec.hpp"
#include "checked_params.hpp"
#include "own_clock.hpp"
#include "ros_sim.hpp"

namespace {

// The world names a folder holds (its *.yaml files), sorted, comma-separated.
std::string shipped_world_names(const std::string& worlds_dir) {
  std::vector<std::string> names;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(worlds_dir, error)) {
    if (entry.path().extension() == ".yaml") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  std::string out;
  for (const auto& name : names) out += (out.empty() ? "" : ", ") + name;
  return out.empty() ? "none found" : out;
}

// The base, odometry and start pose, each checked (see checked_params.hpp).
void read_base_parameters(const ros::NodeHandle& pnh, bullet_turtlebot::SimulationConfig* config,
                          bullet_turtlebot::Pose2D* start) {
  namespace bt = bullet_turtlebot;
  config->seed = static_cast<std::uint64_t>(
      bt::checked_int(pnh, "seed", 1, 0, std::numeric_limits<int>::max(), "a whole number >= 0"));
  pnh.param("odom_noise", config->odometry.enabled, true);
  const std::string noise_rule = "a fraction in [0, 1]";
  bt::OdometryNoise& odom = config->odometry;
  odom.linear = bt::checked_number(pnh, "odom_linear_noise", odom.linear, 0.0, 1.0, noise_rule);
  odom.angular = bt::checked_number(pnh, "odom_angular_noise", odom.angular, 0.0, 1.0, noise_rule);
  odom.angular_per_linear =
      bt::checked_number(pnh, "odom_angular_per_linear_noise", odom.angular_per_linear, 0.0, 1.0, noise_rule);
  odom.yaw_scale = bt::checked_number(pnh, "odom_yaw_scale_error", odom.yaw_scale, -1.0, 1.0, "a fraction in [-1, 1]");
  config->watchdog = bt::checked_number(pnh, "watchdog", config->watchdog, 0.0, 1e6, "0 or more sim seconds");
  bt::DriveLimits& limits = config->limits;
  const double above_zero = bt::above(0.0);
  limits.max_linear = bt::checked_number(pnh, "max_linear", limits.max_linear, above_zero, 100.0, "m/s in (0, 100]");
  limits.max_angular =
      bt::checked_number(pnh, "max_angular", limits.max_angular, above_zero, 100.0, "rad/s in (0, 100]");
  limits.accel_linear =
      bt::checked_number(pnh, "accel_linear", limits.accel_linear, above_zero, 1000.0, "m/s^2 in (0, 1000]");
  limits.accel_angular =
      bt::checked_number(pnh, "accel_angular", limits.accel_angular, above_zero, 1000.0, "rad/s^2 in (0, 1000]");
  config->step = 1.0 / bt::checked_number(pnh, "physics_rate", 100.0, 10.0, 10000.0, "Hz in [10, 10000]");
  const std::string place_rule = "metres within 1e6 of the origin";
  start->x = bt::checked_number(pnh, "x", start->x, -1e6, 1e6, place_rule);
  start->y = bt::checked_number(pnh, "y", start->y, -1e6, 1e6, place_rule);
  start->yaw = bt::checked_number(pnh, "yaw", start->yaw, -1e3, 1e3, "radians within 1000");
}

}  // namespace

int main(int argc, char** argv) {
  // Our own SIGINT handler: roscpp's would shut the node down at once, and the simulator
  // still has to talk to the master on its way out (RosSimulator::restore_use_sim_time).
  // The node keeps its own time rather than follow its own /clock (own_clock.hpp).
  std::string own_clock_word;
  std::vector<char*> args = bullet_turtlebot::argv_with_own_clock(argc, argv, &own_clock_word);
  int args_count = static_cast<int>(args.size()) - 1;
  ros::init(args_count, args.data(), "simulator", ros::init_options::NoSigintHandler);
  std::signal(SIGINT, [](int) { bullet_turtlebot::RosSimulator::request_stop(); });
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  namespace bt = bullet_turtlebot;

  std::string world_name, worlds_dir;
  try {
    world_name = bt::checked_string(pnh, "world", "playground",
                                    "a shipped world's name (" + shipped_world_names(bt::shipped_worlds_dir()) +
                                        ") or a world file's path");
    worlds_dir = bt::checked_string(pnh, "worlds_dir", bt::shipped_worlds_dir(), "a folder of world files");
  } catch (const bt::ParameterError& e) {
    ROS_FATAL("%s", e.what());
    std::fprintf(stderr, "simulator: %s\n", e.what());
    return 2;
  }
  const std::string world_path = bt::resolve_world_path(world_name, worlds_dir);

  bt::WorldSpec spec;
  try {
    spec = bt::load_world_file(world_path);
  } catch (const bt::WorldFileError& e) {
    std::string message = e.what();
    if (world_path != world_name && !std::filesystem::exists(world_path)) {
      message += " (no world named '" + world_name + "' in " + worlds_dir + ": " + shipped_world_names(worlds_dir) +
                 "; or give a world file's path)";
    }
    ROS_FATAL("%s", message.c_str());
    std::fprintf(stderr, "simulator: %s\n", message.c_str());
    return 2;
  } catch (const std::bad_alloc&) {
    ROS_FATAL("world file '%s': too large to load in this machine's memory", world_path.c_str());
    std::fprintf(stderr, "simulator: world file '%s': too large to load in this machine's memory\n",
                 world_path.c_str());
    return 2;
  }

  bt::SimulationConfig config;
  bt::Pose2D start = spec.has_start ? spec.start : bt::Pose2D{};
  const bool chosen = spec.has_start || pnh.hasParam("x") || pnh.hasParam("y");
  try {
    read_base_parameters(pnh, &config, &start);
  } catch (const bt::ParameterError& e) {
    ROS_FATAL("%s", e.what());
    std::fprintf(stderr, "simulator: %s\n", e.what());
    return 2;
  }

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
    const rosbook_env::MasterWatch master_watch;  // re-registers with a restarted roscore
    const int status = simulator.run();
    ros::shutdown();
    return status;
  } catch (const bt::ParameterError& e) {
    ROS_FATAL("%s", e.what());
    std::fprintf(stderr, "simulator: %s\n", e.what());
    return 2;
  } catch (const std::invalid_argument& e) {
    ROS_FATAL("world file '%s': %s", world_path.c_str(), e.what());
    std::fprintf(stderr, "simulator: world file '%s': %s\n", world_path.c_str(), e.what());
    return 2;
  }
}
