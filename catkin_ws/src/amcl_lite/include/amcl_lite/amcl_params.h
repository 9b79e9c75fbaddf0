// The filter's parameters under amcl's names, with amcl's defaults, and their validation.
#pragma once

#include <cmath>
#include <string>

namespace amcl_lite {

struct AmclParams {
  int min_particles = 100;
  int max_particles = 5000;
  double kld_err = 0.01;
  double kld_z = 0.99;
  double odom_alpha1 = 0.2;  // rotation noise from rotation
  double odom_alpha2 = 0.2;  // rotation noise from translation
  double odom_alpha3 = 0.2;  // translation noise from translation
  double odom_alpha4 = 0.2;  // translation noise from rotation
  int laser_max_beams = 30;
  double laser_z_hit = 0.95;
  double laser_z_rand = 0.05;
  double laser_sigma_hit = 0.2;
  double laser_likelihood_max_dist = 2.0;
  double update_min_d = 0.2;
  double update_min_a = M_PI / 6.0;
  int resample_interval = 2;
  double recovery_alpha_slow = 0.0;
  double recovery_alpha_fast = 0.0;
  double initial_pose_x = 0.0;
  double initial_pose_y = 0.0;
  double initial_pose_a = 0.0;
  double initial_cov_xx = 0.5 * 0.5;
  double initial_cov_yy = 0.5 * 0.5;
  double initial_cov_aa = (M_PI / 12.0) * (M_PI / 12.0);
  double transform_tolerance = 0.1;  // s the map -> odom transform is dated ahead
};

// The filter holds max_particles particles from the start (a pose and a weight each): the
// cap keeps that to tens of MB, 200 times amcl's default, instead of whatever a typo asks.
constexpr int kMaxParticlesCap = 1000000;

// Empty when every value is usable; otherwise one message naming the parameter, its value
// and what it must be (the node refuses to start with it).
std::string validate(const AmclParams& p);

}  // namespace amcl_lite
