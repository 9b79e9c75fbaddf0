#include "amcl_lite/particle_filter.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <stdexcept>
#include <unordered_map>

#include "amcl_lite/motion_model.h"

namespace amcl_lite {
namespace {

// amcl's histogram bins for KLD sampling and clustering: 0.5 m x 0.5 m x 10 degrees.
constexpr double kBinSize = 0.5;
constexpr double kBinAngle = 10.0 * M_PI / 180.0;
// Global localization's cloud is at most this many times max_particles (see
// globalParticleCount): a bound on memory and on the few updates it takes to thin it.
constexpr double kGlobalBudget = 50.0;

struct BinKey {
  int x, y, a;
  bool operator==(const BinKey& o) const { return x == o.x && y == o.y && a == o.a; }
};
struct BinHash {
  size_t operator()(const BinKey& k) const {
    return (static_cast<size_t>(k.x) * 73856093u) ^ (static_cast<size_t>(k.y) * 19349663u) ^
           (static_cast<size_t>(k.a) * 83492791u);
  }
};

BinKey binOf(const Pose2& p) {
  return {static_cast<int>(std::floor(p.x / kBinSize)), static_cast<int>(std::floor(p.y / kBinSize)),
          static_cast<int>(std::floor(normalizeAngle(p.theta) / kBinAngle))};
}

}  // namespace

ParticleFilter::ParticleFilter(const AmclParams& params,
                               std::shared_ptr<const LikelihoodField> field, uint32_t seed)
    : params_(params), field_(std::move(field)), rng_(seed) {
  const std::string error = validate(params_);
  if (!error.empty()) throw std::invalid_argument(error);
  if (!field_) throw std::invalid_argument("a map is required");
  initGaussian(Pose2(params.initial_pose_x, params.initial_pose_y, params.initial_pose_a),
               params.initial_cov_xx, params.initial_cov_yy, params.initial_cov_aa);
}

void ParticleFilter::initGaussian(const Pose2& mean, double cov_xx, double cov_yy,
                                  double cov_aa, double cov_xy) {
  // x, y drawn through the Cholesky factor of their 2x2 covariance; yaw independently.
  const double l11 = std::sqrt(std::max(cov_xx, 0.0));
  const double l21 = l11 > 0.0 ? cov_xy / l11 : 0.0;
  const double l22 = std::sqrt(std::max(cov_yy - l21 * l21, 0.0));
  const double la = std::sqrt(std::max(cov_aa, 0.0));
  std::normal_distribution<double> unit(0.0, 1.0);
  particles_.assign(params_.max_particles, Particle{});
  const double w = 1.0 / particles_.size();
  for (auto& p : particles_) {
    const double u = unit(rng_), v = unit(rng_);
    p.pose = Pose2(mean.x + l11 * u, mean.y + l21 * u + l22 * v,
                   normalizeAngle(mean.theta + la * unit(rng_)));
    p.weight = w;
  }
  updates_since_resample_ = 0;
  w_slow_ = w_fast_ = 0.0;
}

Pose2 ParticleFilter::randomFreePose() {
  const auto& cells = field_->freeCells();
  if (cells.empty()) throw std::runtime_error("the map has no free cell to place particles in");
  const auto& c = cells[std::uniform_int_distribution<size_t>(0, cells.size() - 1)(rng_)];
  return Pose2(c.first, c.second, std::uniform_real_distribution<double>(-M_PI, M_PI)(rng_));
}

size_t ParticleFilter::globalParticleCount() const {
  // Enough particles that the bin of amcl's KLD histogram (kBinSize x kBinSize x kBinAngle)
  // holding the true pose is empty with probability at most 1 - kld_z, amcl's confidence
  // for its KLD bound: with particles spread uniformly, a bin's count is Poisson, so each
  // free bin needs ln(1 / (1 - kld_z)) of them on average (4.6 at amcl's 0.99). With fewer,
  // the Kinect's 58-degree view finds many places that match as well as the nearest
  // particle to the truth, and the filter settles on one of them.
  const double cell = field_->resolution();
  const double free_area = static_cast<double>(field_->freeCells().size()) * cell * cell;
  const double bins = free_area / (kBinSize * kBinSize) * (2.0 * M_PI / kBinAngle);
  const double wanted = std::ceil(bins * std::log(1.0 / (1.0 - params_.kld_z)));
  // Bounded by a compute budget: one global update costs at most that many normal ones.
  const double budget = kGlobalBudget * static_cast<double>(params_.max_particles);
  return static_cast<size_t>(std::max<double>(params_.max_particles, std::min(wanted, budget)));
}

void ParticleFilter::initGlobal() {
  particles_.assign(globalParticleCount(), Particle{});
  const double w = 1.0 / particles_.size();
  for (auto& p : particles_) {
    p.pose = randomFreePose();
    p.weight = w;
  }
  updates_since_resample_ = 0;
  w_slow_ = w_fast_ = 0.0;
}

void ParticleFilter::predict(const Pose2& old_odom, const Pose2& new_odom) {
  const OdomNoise noise{params_.odom_alpha1, params_.odom_alpha2, params_.odom_alpha3,
                        params_.odom_alpha4};
  for (auto& p : particles_) p.pose = sampleDiffMotion(p.pose, old_odom, new_odom, noise, rng_);
}

std::vector<int> ParticleFilter::beamIndices(int count, int max_beams) {
  std::vector<int> out;
  if (count <= 0) return out;
  const int used = std::min(count, max_beams);
  if (used == 1) return {count / 2};
  // Evenly from the first to the last reading, so a narrow sensor still spans its whole view.
  for (int i = 0; i < used; ++i)
    out.push_back(static_cast<int>(std::lround(static_cast<double>(i) * (count - 1) / (used - 1))));
  return out;
}

void ParticleFilter::correct(const ScanObservation& scan) {
  const double denom = 2.0 * params_.laser_sigma_hit * params_.laser_sigma_hit;
  const double z_rand = params_.laser_z_rand / scan.range_max;
  // Beam ends in the laser's frame, once per scan. As amcl's likelihood_field model, readings
  // outside [range_min, range_max) (max range, too close, NaN, +-inf) carry no hit.
  std::vector<std::pair<double, double>> ends;
  ends.reserve(scan.beams.size());
  for (const Beam& b : scan.beams)
    if (b.range >= scan.range_min && b.range < scan.range_max)
      ends.emplace_back(b.range * std::cos(b.angle), b.range * std::sin(b.angle));
  double total = 0.0;
  for (auto& p : particles_) {
    const Pose2 laser = p.pose * scan.laser_in_base;
    const double c = std::cos(laser.theta), s = std::sin(laser.theta);
    // amcl's likelihood_field model: sum of cubed beam probabilities, added to 1 so one bad
    // beam cannot zero a particle (a heuristic amcl uses for robustness).
    double weight = 1.0;
    for (const auto& [lx, ly] : ends) {
      const double z = field_->distance(laser.x + c * lx - s * ly, laser.y + s * lx + c * ly);
      const double pz = params_.laser_z_hit * std::exp(-z * z / denom) + z_rand;
      weight += pz * pz * pz;
    }
    p.weight *= weight;
    total += p.weight;
  }
  if (!(total > 0.0)) {
    for (auto& p : particles_) p.weight = 1.0 / particles_.size();
    return;
  }
  for (auto& p : particles_) p.weight /= total;
  // Augmented MCL: short- and long-term averages of the measurement likelihood.
  const double w_avg = total / particles_.size();
  if (w_slow_ == 0.0) w_slow_ = w_avg;
  else w_slow_ += params_.recovery_alpha_slow * (w_avg - w_slow_);
  if (w_fast_ == 0.0) w_fast_ = w_avg;
  else w_fast_ += params_.recovery_alpha_fast * (w_avg - w_fast_);
  // A cloud larger than max_particles (global localization's start) is thinned by
  // resampling only once its weights are carried by no more than max_particles particles
  // (effective sample size 1 / sum w^2): earlier, drawing max_particles from it would lose
  // the few particles near the truth, which the summed-cubes model favours only mildly.
  if (particles_.size() > static_cast<size_t>(params_.max_particles)) {
    double sum_sq = 0.0;
    for (const auto& p : particles_) sum_sq += p.weight * p.weight;
    if (1.0 / sum_sq > params_.max_particles) return;
  }
  if (++updates_since_resample_ >= params_.resample_interval) {
    resample();
    updates_since_resample_ = 0;
  }
}

size_t ParticleFilter::kldLimit(size_t bins) const {
  if (bins <= 1) return params_.max_particles;
  // Fox's bound with the Wilson-Hilferty approximation. As amcl does, kld_z enters as the
  // normal quantile itself (0.99 by default), which keeps amcl's particle counts.
  const double k = static_cast<double>(bins - 1);
  const double b = 2.0 / (9.0 * k);
  const double x = 1.0 - b + std::sqrt(b) * params_.kld_z;
  const double n = std::ceil(k / (2.0 * params_.kld_err) * x * x * x);
  return static_cast<size_t>(
      std::clamp(n, static_cast<double>(params_.min_particles), static_cast<double>(params_.max_particles)));
}

void ParticleFilter::resample() {
  std::vector<double> cumulative(particles_.size());
  double sum = 0.0;
  for (size_t i = 0; i < particles_.size(); ++i) cumulative[i] = (sum += particles_[i].weight);
  double w_diff = 0.0;
  if (params_.recovery_alpha_slow > 0.0 && w_slow_ > 0.0)
    w_diff = std::max(0.0, 1.0 - w_fast_ / w_slow_);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::unordered_map<BinKey, int, BinHash> bins;
  // KLD sampling sets how many particles to keep: draws are binned until their count
  // passes the bound for the bins they fill (Fox 2003, as amcl). The kept particles are then
  // drawn by low-variance (systematic) resampling (Probabilistic Robotics, table 4.4) rather
  // than by those independent draws: a hypothesis holding a share w of the weight keeps
  // floor or ceil of w * n copies, where independent draws lose it with probability
  // (1 - w)^n. While the cloud is still many-moded (global localization with the Kinect's
  // narrow view), that chance, repeated every update, loses the true pose.
  std::vector<Particle> next;
  next.reserve(params_.max_particles);
  size_t drawn = 0;
  while (drawn < static_cast<size_t>(params_.max_particles)) {
    Pose2 pose;
    if (unit(rng_) < w_diff) {
      pose = randomFreePose();
      next.push_back(Particle{pose, 0.0});
    } else {
      const double r = unit(rng_) * sum;
      const size_t i = std::min<size_t>(
          std::upper_bound(cumulative.begin(), cumulative.end(), r) - cumulative.begin(),
          particles_.size() - 1);
      pose = particles_[i].pose;
    }
    ++bins[binOf(pose)];
    ++drawn;
    if (drawn >= static_cast<size_t>(params_.min_particles) && drawn >= kldLimit(bins.size()))
      break;
  }
  const size_t resampled = drawn - next.size();
  if (resampled > 0) {
    const double step = sum / resampled;
    double target = unit(rng_) * step;
    size_t i = 0;
    for (size_t k = 0; k < resampled; ++k, target += step) {
      while (i + 1 < particles_.size() && cumulative[i] < target) ++i;
      next.push_back(Particle{particles_[i].pose, 0.0});
    }
  }
  for (auto& p : next) p.weight = 1.0 / next.size();
  particles_.swap(next);
  // The new particles are unbiased samples: restart the likelihood averages' drift check.
  if (w_diff > 0.0) w_slow_ = w_fast_ = 0.0;
}

PoseEstimate ParticleFilter::estimate() const {
  // Group particles into clusters of touching histogram bins and report the heaviest one,
  // so a multi-modal cloud (global localization) gives a pose rather than an average of
  // places the robot cannot all be in.
  std::unordered_map<BinKey, std::vector<size_t>, BinHash> bins;
  for (size_t i = 0; i < particles_.size(); ++i) bins[binOf(particles_[i].pose)].push_back(i);
  std::unordered_map<BinKey, int, BinHash> cluster_of;
  std::vector<std::vector<size_t>> clusters;
  for (const auto& entry : bins) {
    if (cluster_of.count(entry.first)) continue;
    const int id = static_cast<int>(clusters.size());
    clusters.emplace_back();
    std::deque<BinKey> open{entry.first};
    cluster_of[entry.first] = id;
    while (!open.empty()) {
      const BinKey k = open.front();
      open.pop_front();
      const auto& members = bins.at(k);
      clusters[id].insert(clusters[id].end(), members.begin(), members.end());
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          for (int da = -1; da <= 1; ++da) {
            // Yaw bins wrap around at +-pi.
            const int bins_per_turn = static_cast<int>(std::ceil(2.0 * M_PI / kBinAngle));
            int a = k.a + da;
            const int a_min = static_cast<int>(std::floor(-M_PI / kBinAngle));
            if (a < a_min) a += bins_per_turn;
            if (a >= a_min + bins_per_turn) a -= bins_per_turn;
            const BinKey n{k.x + dx, k.y + dy, a};
            if (bins.count(n) && !cluster_of.count(n)) {
              cluster_of[n] = id;
              open.push_back(n);
            }
          }
    }
  }
  const std::vector<size_t>* best = nullptr;
  double best_weight = -1.0;
  for (const auto& c : clusters) {
    double w = 0.0;
    for (size_t i : c) w += particles_[i].weight;
    if (w > best_weight) {
      best_weight = w;
      best = &c;
    }
  }
  PoseEstimate out;
  if (!best || !(best_weight > 0.0)) return out;
  double mx = 0.0, my = 0.0, mc = 0.0, ms = 0.0;
  for (size_t i : *best) {
    const Particle& p = particles_[i];
    mx += p.weight * p.pose.x;
    my += p.weight * p.pose.y;
    mc += p.weight * std::cos(p.pose.theta);
    ms += p.weight * std::sin(p.pose.theta);
  }
  mx /= best_weight;
  my /= best_weight;
  out.mean = Pose2(mx, my, std::atan2(ms, mc));
  double cxx = 0.0, cxy = 0.0, cyy = 0.0, caa = 0.0;
  for (size_t i : *best) {
    const Particle& p = particles_[i];
    const double ex = p.pose.x - mx, ey = p.pose.y - my, ea = normalizeAngle(p.pose.theta - out.mean.theta);
    cxx += p.weight * ex * ex;
    cxy += p.weight * ex * ey;
    cyy += p.weight * ey * ey;
    caa += p.weight * ea * ea;
  }
  out.covariance = {cxx / best_weight, cxy / best_weight, 0.0, cxy / best_weight, cyy / best_weight,
                    0.0, 0.0, 0.0, caa / best_weight};
  return out;
}

}  // namespace amcl_lite
