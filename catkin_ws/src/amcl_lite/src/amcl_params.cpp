#include "amcl_lite/amcl_params.h"

#include <sstream>

namespace amcl_lite {
namespace {

std::string bad(const std::string& name, double value, const std::string& rule) {
  std::ostringstream out;
  out << "parameter " << name << " = " << value << " is invalid: it must be " << rule;
  return out.str();
}

}  // namespace

std::string validate(const AmclParams& p) {
  const struct {
    const char* name;
    double value;
  } finite[] = {{"kld_err", p.kld_err},
                {"kld_z", p.kld_z},
                {"odom_alpha1", p.odom_alpha1},
                {"odom_alpha2", p.odom_alpha2},
                {"odom_alpha3", p.odom_alpha3},
                {"odom_alpha4", p.odom_alpha4},
                {"laser_z_hit", p.laser_z_hit},
                {"laser_z_rand", p.laser_z_rand},
                {"laser_sigma_hit", p.laser_sigma_hit},
                {"laser_likelihood_max_dist", p.laser_likelihood_max_dist},
                {"update_min_d", p.update_min_d},
                {"update_min_a", p.update_min_a},
                {"recovery_alpha_slow", p.recovery_alpha_slow},
                {"recovery_alpha_fast", p.recovery_alpha_fast},
                {"initial_pose_x", p.initial_pose_x},
                {"initial_pose_y", p.initial_pose_y},
                {"initial_pose_a", p.initial_pose_a},
                {"initial_cov_xx", p.initial_cov_xx},
                {"initial_cov_yy", p.initial_cov_yy},
                {"initial_cov_aa", p.initial_cov_aa},
                {"transform_tolerance", p.transform_tolerance}};
  for (const auto& f : finite)
    if (!std::isfinite(f.value)) return bad(f.name, f.value, "a finite number");
  if (p.min_particles < 1) return bad("min_particles", p.min_particles, ">= 1");
  if (p.max_particles < p.min_particles)
    return bad("max_particles", p.max_particles, ">= min_particles (" +
                                                     std::to_string(p.min_particles) + ")");
  if (p.max_particles > kMaxParticlesCap)
    return bad("max_particles", p.max_particles,
               "<= " + std::to_string(kMaxParticlesCap) + " (the filter holds that many)");
  if (!(p.kld_err > 0.0 && p.kld_err < 1.0)) return bad("kld_err", p.kld_err, "in (0, 1)");
  if (!(p.kld_z > 0.5 && p.kld_z < 1.0)) return bad("kld_z", p.kld_z, "in (0.5, 1)");
  const struct {
    const char* name;
    double value;
  } non_negative[] = {{"odom_alpha1", p.odom_alpha1},   {"odom_alpha2", p.odom_alpha2},
                      {"odom_alpha3", p.odom_alpha3},   {"odom_alpha4", p.odom_alpha4},
                      {"laser_z_hit", p.laser_z_hit},   {"laser_z_rand", p.laser_z_rand},
                      {"update_min_d", p.update_min_d}, {"update_min_a", p.update_min_a},
                      {"initial_cov_xx", p.initial_cov_xx}, {"initial_cov_yy", p.initial_cov_yy},
                      {"initial_cov_aa", p.initial_cov_aa}};
  for (const auto& f : non_negative)
    if (f.value < 0.0) return bad(f.name, f.value, ">= 0");
  if (p.laser_z_hit + p.laser_z_rand <= 0.0)
    return bad("laser_z_hit + laser_z_rand", p.laser_z_hit + p.laser_z_rand, "> 0");
  if (p.laser_sigma_hit <= 0.0) return bad("laser_sigma_hit", p.laser_sigma_hit, "> 0");
  if (p.laser_likelihood_max_dist <= 0.0)
    return bad("laser_likelihood_max_dist", p.laser_likelihood_max_dist, "> 0");
  if (p.transform_tolerance < 0.0)
    return bad("transform_tolerance", p.transform_tolerance, "seconds >= 0");
  if (p.laser_max_beams < 2) return bad("laser_max_beams", p.laser_max_beams, ">= 2");
  if (p.resample_interval < 1) return bad("resample_interval", p.resample_interval, ">= 1");
  if (p.recovery_alpha_slow < 0.0 || p.recovery_alpha_slow > 1.0)
    return bad("recovery_alpha_slow", p.recovery_alpha_slow, "in [0, 1]");
  if (p.recovery_alpha_fast < 0.0 || p.recovery_alpha_fast > 1.0)
    return bad("recovery_alpha_fast", p.recovery_alpha_fast, "in [0, 1]");
  if (p.recovery_alpha_slow > 0.0 && p.recovery_alpha_fast <= p.recovery_alpha_slow)
    return bad("recovery_alpha_fast", p.recovery_alpha_fast,
               "> recovery_alpha_slow when recovery is on");
  return {};
}

}  // namespace amcl_lite
