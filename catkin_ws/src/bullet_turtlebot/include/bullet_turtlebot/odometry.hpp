// Wheel odometry with realistic drift: a random walk in distance and heading whose variance
// grows with the distance and angle actually travelled, plus a small systematic yaw scale
// error. Nothing is drawn at rest, so odometry never creeps. Seeded for reproducible runs.
#pragma once

#include <cstdint>
#include <random>

#include "bullet_turtlebot/types.hpp"

namespace bullet_turtlebot {

struct OdometryNoise {
  bool enabled = true;
  double linear = 0.01;             // m per sqrt(m) travelled (1 sigma)
  double angular = 0.02;            // rad per sqrt(rad) turned
  double angular_per_linear = 0.01; // rad per sqrt(m) travelled
  double yaw_scale = 0.005;         // systematic relative error of measured rotation
};

class OdometryModel {
 public:
  OdometryModel(const OdometryNoise& noise, std::uint64_t seed);

  // Adds one step of true motion (forward distance, rotation, both in the robot frame over
  // dt); returns the measured increment applied to the odometry pose.
  void update(double forward, double rotation, double dt);

  const Pose2D& pose() const { return pose_; }
  double linear_velocity() const { return v_; }
  double angular_velocity() const { return w_; }
  double travelled() const { return travelled_; }
  double turned() const { return turned_; }
  const OdometryNoise& noise() const { return noise_; }

 private:
  OdometryNoise noise_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> gauss_{0.0, 1.0};
  Pose2D pose_;
  double v_ = 0.0, w_ = 0.0;
  double travelled_ = 0.0, turned_ = 0.0;
};

}  // namespace bullet_turtlebot
