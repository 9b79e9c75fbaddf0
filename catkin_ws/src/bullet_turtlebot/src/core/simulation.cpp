#include "bullet_turtlebot/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace bullet_turtlebot {

bool find_free_position(const World& world, const RobotGeometry& geometry, const Eigen::Vector2d& near,
                        double max_distance, Eigen::Vector2d* found) {
  const double step = 0.05;
  const int rings = static_cast<int>(std::ceil(max_distance / step));
  auto free_at = [&](const Eigen::Vector2d& p) {
    return !world.cylinder_collides(p, geometry.radius, geometry.height, geometry.clearance);
  };
  // Square rings grow in Chebyshev distance: after a first hit at Euclidean distance d, rings
  // up to d / step may still hold a nearer free cell.
  bool have = false;
  double best = 0.0;
  int last_ring = rings;
  for (int ring = 0; ring <= last_ring; ++ring) {
    for (int i = -ring; i <= ring; ++i) {
      for (int j = -ring; j <= ring; ++j) {
        if (std::max(std::abs(i), std::abs(j)) != ring) continue;
        const Eigen::Vector2d p = near + step * Eigen::Vector2d(i, j);
        const double d = (p - near).norm();
        if ((!have || d < best) && free_at(p)) {
          have = true;
          best = d;
          *found = p;
          last_ring = std::min(rings, static_cast<int>(std::ceil(d / step)));
        }
      }
    }
  }
  return have;
}

Simulation::Simulation(std::shared_ptr<const World> world, const SimulationConfig& config, const Pose2D& start)
    : world_(std::move(world)),
      config_(config),
      pose_(start),
      odometry_(config.odometry, config.seed),
      sensor_rng_(config.seed * 7919 + 17) {
  const RobotGeometry& g = config_.geometry;
  if (world_->cylinder_collides(Eigen::Vector2d(start.x, start.y), g.radius, g.height, g.clearance)) {
    throw std::invalid_argument("start pose (" + std::to_string(start.x) + ", " + std::to_string(start.y) +
                                ") puts the robot inside an obstacle; choose another start (launch args x:= y:=, "
                                "params ~x ~y, or `start: [x, y, yaw]` in the world file)");
  }
}

void Simulation::command(double linear, double angular) {
  clamp_command(config_.limits, &linear, &angular);
  cmd_v_ = linear;
  cmd_w_ = angular;
  last_command_ = time_;
}

bool Simulation::teleport(const Pose2D& pose) {
  const RobotGeometry& g = config_.geometry;
  if (world_->cylinder_collides(Eigen::Vector2d(pose.x, pose.y), g.radius, g.height, g.clearance)) return false;
  pose_ = Pose2D{pose.x, pose.y, normalize_angle(pose.yaw)};
  v_ = w_ = cmd_v_ = cmd_w_ = 0.0;
  return true;
}

std::vector<BumperChange> Simulation::step() {
  const double dt = config_.step;
  std::vector<BumperChange> changes;
  if (time_ - last_command_ > config_.watchdog) {
    cmd_v_ = 0.0;
    cmd_w_ = 0.0;
  }
  v_ = ramp(v_, cmd_v_, config_.limits.accel_linear, dt);
  w_ = ramp(w_, cmd_w_, config_.limits.accel_angular, dt);

  const Pose2D before = pose_;
  Pose2D after = integrate_arc(pose_, v_, w_, dt);
  const RobotGeometry& g = config_.geometry;
  const Eigen::Vector2d from(before.x, before.y), to(after.x, after.y);
  const double length = (to - from).norm();
  std::array<bool, 3> pressed{{false, false, false}};
  bool blocked = false;
  if (length > 0) {
    const SweepResult sweep = world_->sweep_cylinder(from, to, g.radius, g.height, g.clearance);
    if (sweep.hit) {
      // Stop just short of the contact; the wheels stall, so odometry sees no motion either.
      blocked = true;
      const double keep = std::max(0.0, sweep.fraction - 1e-3 / length);
      const Eigen::Vector2d stop = from + keep * (to - from);
      after.x = stop.x();
      after.y = stop.y();
      v_ = 0.0;
      ++collisions_;
      // Which bumper: bearing of the contact (against the motion) in the robot frame.
      const double bearing = normalize_angle(std::atan2(-sweep.normal.y(), -sweep.normal.x()) - before.yaw);
      if (std::abs(bearing) <= M_PI / 2) {
        pressed[std::abs(bearing) < M_PI / 6 ? kBumperCenter : (bearing > 0 ? kBumperLeft : kBumperRight)] = true;
      }
    }
  }
  // A bumper stays pressed while the robot pushes or rests against the obstacle and is
  // released once it moves freely.
  const bool moved_freely = !blocked && length > 1e-6;
  for (int b = 0; b < 3; ++b) {
    bool state = bumpers_[b];
    if (pressed[b]) state = true;
    else if (moved_freely || blocked) state = false;
    if (state != bumpers_[b]) {
      bumpers_[b] = state;
      changes.push_back(BumperChange{b, state});
    }
  }

  const double dx = after.x - before.x, dy = after.y - before.y;
  const double forward = dx * std::cos(before.yaw + w_ * dt / 2) + dy * std::sin(before.yaw + w_ * dt / 2);
  odometry_.update(forward, normalize_angle(after.yaw - before.yaw), dt);
  pose_ = after;
  time_ += dt;
  return changes;
}

SensorPose Simulation::sensor_pose(const Eigen::Vector3d& mount) const {
  const double c = std::cos(pose_.yaw), s = std::sin(pose_.yaw);
  SensorPose p;
  p.position = Eigen::Vector3d(pose_.x + c * mount.x() - s * mount.y(), pose_.y + s * mount.x() + c * mount.y(),
                               mount.z());
  p.yaw = pose_.yaw;
  return p;
}

}  // namespace bullet_turtlebot
