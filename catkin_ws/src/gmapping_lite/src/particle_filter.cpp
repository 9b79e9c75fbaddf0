#include "gmapping_lite/particle_filter.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace gmapping_lite {

namespace {
// What the motion model's spread leaves out (slip, timing, the map's own error). Tuned on
// exploration runs in the simulator's office world (Turtlebot odometry, 58-degree fake laser)
// and the synthetic office tour: wider floors let weak views (a far, noisy wall seen through a
// door) turn the pose; narrower ones hold it to odometry's scale error.
constexpr double kPriorFloorXY = 0.08;     // m
constexpr double kPriorFloorTheta = 0.03;  // rad
}  // namespace

ParticleFilter::ParticleFilter(const SlamParams& params)
    : params_(params),
      motion_(params.motion),
      matcher_(params.matcher),
      rng_(params.seed) {
  particles_.resize(static_cast<std::size_t>(std::max(1, params.particles)));
  for (auto& p : particles_) p.map = GridMap(params.delta);
}

std::vector<double> ParticleFilter::weights() const {
  // gmapping: w = exp(gain * (l - lmax)), gain = 1 / (ogain * N).
  const double gain = 1.0 / (params_.ogain * double(particles_.size()));
  double lmax = -INFINITY;
  for (const auto& p : particles_) lmax = std::max(lmax, p.log_weight);
  std::vector<double> w(particles_.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    w[i] = std::exp(gain * (particles_[i].log_weight - lmax));
    sum += w[i];
  }
  for (double& x : w) x /= sum;
  return w;
}

double ParticleFilter::neff() const {
  double s = 0.0;
  for (double w : weights()) s += w * w;
  return 1.0 / s;
}

double ParticleFilter::entropy() const {
  double h = 0.0;
  for (double w : weights())
    if (w > 0.0) h -= w * std::log(w);
  return h;
}

std::size_t ParticleFilter::bestIndex() const {
  std::size_t best = 0;
  for (std::size_t i = 1; i < particles_.size(); ++i)
    if (particles_[i].weight_sum > particles_[best].weight_sum) best = i;
  return best;
}

Pose2 ParticleFilter::mapToOdom() const {
  if (!initialized_) return {};
  return best().pose * last_odom_.inverse();
}

void ParticleFilter::resample(const std::vector<double>& weights) {
  // Low-variance (systematic) resampling; copies share map patches and trajectory nodes.
  const std::size_t n = particles_.size();
  std::vector<Particle> next;
  next.reserve(n);
  const double step = 1.0 / double(n);
  double u = std::uniform_real_distribution<double>(0.0, step)(rng_);
  double c = weights[0];
  std::size_t i = 0;
  for (std::size_t m = 0; m < n; ++m) {
    while (u > c && i + 1 < n) c += weights[++i];
    next.push_back(particles_[i]);
    next.back().log_weight = 0.0;
    u += step;
  }
  particles_ = std::move(next);
}

UpdateReport ParticleFilter::addScan(const Pose2& odom, double stamp, const LaserGeometry& laser,
                                     const Ranges& ranges) {
  UpdateReport report;
  if (!initialized_) {
    // The map frame starts aligned with odom, as in gmapping. One map is built and shared
    // by every particle (copy-on-write), not built once per particle.
    GridMap first(params_.delta);
    registerScan(&first, odom, laser, ranges, params_.matcher.max_range,
                 params_.matcher.max_urange);
    const auto root = std::make_shared<TrajectoryNode>(TrajectoryNode{odom, stamp, nullptr});
    for (auto& p : particles_) {
      p.pose = odom;
      p.map = first;
      p.trajectory = root;
    }
    initialized_ = true;
    last_odom_ = previous_odom_ = odom;
    last_update_stamp_ = stamp;
    report.processed = true;
    report.update_index = updates_++;
    report.neff = double(particles_.size());
    report.best_pose = odom;
    return report;
  }

  const Pose2 step = odom.relativeTo(previous_odom_);
  linear_distance_ += std::hypot(step.x, step.y);
  angular_distance_ += std::fabs(step.theta);
  previous_odom_ = odom;
  const bool due = linear_distance_ >= params_.linear_update ||
                   angular_distance_ >= params_.angular_update ||
                   (params_.temporal_update >= 0.0 &&
                    stamp - last_update_stamp_ > params_.temporal_update);
  if (!due) return report;

  const ScanPoints points = matcher_.matchPoints(laser, ranges);
  // The match may move a particle about as far as odometry could plausibly be off: the
  // motion model's spread for this increment, plus a floor for what it does not model.
  const Pose2 inc = odom.relativeTo(last_odom_);
  const double dist = std::hypot(inc.x, inc.y), turn = std::fabs(inc.theta);
  const OdometryPrior prior{
      kPriorFloorXY + params_.motion.srr * dist + params_.motion.str * turn,
      kPriorFloorTheta + params_.motion.stt * turn + params_.motion.srt * dist};
  double best_score = -1.0;
  for (auto& p : particles_) {
    p.pose = motion_.sample(p.pose, last_odom_, odom, rng_);
    matcher_.prepare(p.map, p.pose, points);
    Pose2 corrected;
    const double score = matcher_.optimize(p.pose, points, &corrected, prior);
    if (score > params_.minimum_score) {
      p.pose = corrected;
    } else {
      ++report.failed_matches;
    }
    double sc = 0.0;
    const double l = matcher_.likelihood(p.pose, points, &sc);
    p.log_weight += l;
    p.weight_sum += l;
    best_score = std::max(best_score, score);
  }

  const std::vector<double> w = weights();
  double sum_sq = 0.0;
  for (double x : w) sum_sq += x * x;
  report.neff = 1.0 / sum_sq;
  if (report.neff < params_.resample_threshold * double(particles_.size())) {
    resample(w);
    report.resampled = true;
  }
  for (auto& p : particles_) {
    registerScan(&p.map, p.pose, laser, ranges, params_.matcher.max_range,
                 params_.matcher.max_urange);
    p.trajectory = std::make_shared<TrajectoryNode>(TrajectoryNode{p.pose, stamp, p.trajectory});
  }

  last_odom_ = odom;
  linear_distance_ = angular_distance_ = 0.0;
  last_update_stamp_ = stamp;
  report.processed = true;
  report.update_index = updates_++;
  report.best_score = best_score;
  report.best_pose = best().pose;
  return report;
}

}  // namespace gmapping_lite
