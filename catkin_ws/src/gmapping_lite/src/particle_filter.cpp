#include "gmapping_lite/particle_filter.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace gmapping_lite {


namespace {
MatcherParams withMapResolution(MatcherParams m, double delta) {
  // Beams ending within one map cell of each other are one observation to the map.
  if (m.merge_distance <= 0.0) m.merge_distance = delta;
  return m;
}
}  // namespace

ParticleFilter::ParticleFilter(const SlamParams& params)
    : params_(params),
      motion_(params.motion),
      matcher_(withMapResolution(params.matcher, params.delta)),
      local_matcher_(withMapResolution(params.matcher, params.delta)),
      loop_closer_(withMapResolution(params.matcher, params.delta), params.delta),
      rng_(params.seed) {
  particles_.resize(static_cast<std::size_t>(std::max(1, params.particles)));
  for (auto& p : particles_) p.map = GridMap(params.delta);
}

std::vector<double> relativeMatchEvidence(const std::vector<double>& nis) {
  double sum = 0.0;
  int matched = 0;
  for (double x : nis)
    if (std::isfinite(x)) sum += x, ++matched;
  std::vector<double> evidence(nis.size(), 0.0);
  if (matched == 0) return evidence;
  const double mean = sum / matched;
  for (std::size_t i = 0; i < nis.size(); ++i)
    if (std::isfinite(nis[i])) evidence[i] = -0.5 * (nis[i] - mean);
  return evidence;
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

OdometryPrior ParticleFilter::odometryPrior(const Pose2& inc) const {
  // How far a match may move a particle from odometry's prediction (standard deviations):
  // - the motion model's spread for this increment (srr, srt, str, stt as gmapping uses them);
  // - timing: a scan paired with odometry from another instant than the one it saw is placed
  //   off by the distance and angle the robot covers in between; a constant offset cancels
  //   between the two ends of the increment while the speeds hold, so it counts as far as they
  //   changed (starting or stopping a turn on the spot). The offset's sd has two parts:
  //   odometry is known at its own samples, and a scan may be paired with the sample a whole
  //   odometry period To from what it saw (Stage publishes a world step's pose with the next
  //   step's scan), an offset of To; and the laser's sweep or acquisition within its own period
  //   Ts is uniform over it, sd Ts / sqrt(12). Together sqrt(Ts^2 / 12 + To^2). While To is
  //   not known (setOdometryPeriod), Ts alone: the bound of an offset within one scan period.
  // Nothing else: the map's own resolution limits the scan, not odometry, and is in the scan's
  // likelihood (sigma); a floor here would let a scan move a pose odometry knows well.
  const double dist = std::hypot(inc.x, inc.y), turn = std::fabs(inc.theta);
  const double ts = scan_period_ > 0.0 ? scan_period_ : 0.0, to = odometry_period_;
  const double period = to > 0.0 ? std::sqrt(ts * ts / 12.0 + to * to) : ts;
  const MotionNoise& m = params_.motion;
  return {m.srr * dist + m.str * turn + period * std::fabs(speed_ - last_update_speed_),
          m.stt * turn + m.srt * dist + period * std::fabs(turn_rate_ - last_update_turn_rate_)};
}

double ParticleFilter::rescue(const GridMap& map, const Pose2& predicted, const ScanPoints& points,
                              const OdometryPrior& prior, double score, Pose2* corrected) {
  // The climb found nothing worth keeping although the scan could match: odometry may be off
  // by more than a climb reaches (a wheel slip, a late stamp while turning). Search the
  // prior's three-sigma window exhaustively on a grid of at most 21 steps per axis, no finer
  // than two cells, then climb from the grid's best. The result must score as a match and most
  // of the points the map can check must agree with it.
  double far = params_.delta;
  for (const auto& q : points.points) far = std::max(far, std::hypot(q.hx, q.hy));
  const double window_xy = 3.0 * prior.sigma_xy, window_theta = std::min(M_PI, 3.0 * prior.sigma_theta);
  const double step_xy = std::max(2.0 * params_.delta, window_xy / 10.0);
  const double step_theta = std::max(step_xy / far, window_theta / 10.0);
  matcher_.prepare(map, predicted, points, window_xy + window_theta * far);
  const std::vector<ScanMatcher::Candidate> grid =
      matcher_.search(predicted, points, window_xy, window_theta, step_xy, step_theta);
  const ScanMatcher::Candidate* top = &grid.front();
  for (const auto& c : grid)
    if (c.value > top->value) top = &c;
  Pose2 found;
  const double found_score = matcher_.optimizeFrom(top->pose, predicted, points, &found, prior);
  // At least a point per degree of freedom, and twice as many points agreeing with the map as
  // contradicting it.
  int matched = 0, contradicting = 0;
  matcher_.agreement(found, points, &matched, &contradicting);
  if (found_score <= score || matched < 3 || matched < 2 * contradicting) return score;
  // The window must hold one place that fits, not several (a pillar fits from any side): the
  // same test as a loop closure's, against the scan's own information at the found pose.
  if (ScanMatcher::margin(grid, *top, matcher_.information(found, points, {}), step_xy,
                          step_theta) < std::log(double(grid.size())))
    return score;
  *corrected = found;
  return found_score;
}

std::shared_ptr<const LaserGeometry> ParticleFilter::sharedLaser(const LaserGeometry& laser) {
  auto same = [&](const LaserGeometry& a) {
    if (a.beams.size() != laser.beams.size() || a.origin.x != laser.origin.x ||
        a.origin.y != laser.origin.y)
      return false;
    for (std::size_t i = 0; i < a.beams.size(); ++i)
      if (a.beams[i].angle != laser.beams[i].angle || a.beams[i].scale != laser.beams[i].scale)
        return false;
    return true;
  };
  if (!laser_ || !same(*laser_)) laser_ = std::make_shared<const LaserGeometry>(laser);
  return laser_;
}

void ParticleFilter::backEnd(const ScanPoints& points, const OdometryPrior& prior,
                             UpdateReport* report) {
  Particle& best = particles_[bestIndex()];
  std::vector<const TrajectoryNode*> chain = chainOf(best.trajectory.get());
  if (chain.size() < 2) return;
  // The step to the newest node as its scan matches the recent scans alone: the front end
  // matched it against the whole map, and on returning to a place mapped long ago that match
  // carries the drift accumulated since (a jump the graph must be free to spread out).
  std::vector<double> var_xy, var_theta;
  relativeUncertainty(std::vector<const TrajectoryNode*>(chain.begin(), chain.end() - 1), loops_,
                      &var_xy, &var_theta);
  const TrajectoryNode& newest = *chain.back();
  const TrajectoryNode& previous = *chain[chain.size() - 2];
  GridMap local(params_.delta);
  const double half_cell = 0.5 * params_.delta;
  double mean_range = 0.0;
  for (const auto& q : points.points) mean_range += std::hypot(q.hx, q.hy);
  mean_range = points.points.empty() ? 0.0 : mean_range / double(points.points.size());
  int recent = 0;
  const int most = 2 * static_cast<int>(std::ceil(
                           std::min(params_.matcher.max_range, params_.matcher.max_urange)));
  for (int k = static_cast<int>(chain.size()) - 2; k >= 0 && recent < most; --k) {
    const double loose = std::sqrt(var_xy[k]) + std::sqrt(var_theta[k]) * mean_range;
    if (loose >= half_cell && recent > 0) break;
    const TrajectoryNode& n = *chain[static_cast<std::size_t>(k)];
    registerScan(&local, n.pose, *n.laser, *n.ranges, params_.matcher.max_range,
                 params_.matcher.max_urange);
    ++recent;
  }
  Pose2 local_pose = newest.pose;
  Information info = best.information;
  if (points.points.size() >= 3) {
    local_matcher_.prepare(local, newest.pose, points);
    Pose2 predicted = previous.pose * newest.step;  // where the front end put it
    const double score =
        local_matcher_.optimizeFrom(predicted, predicted, points, &local_pose, prior);
    if (score > params_.minimum_score) {
      info = local_matcher_.information(local_pose, points, prior);
    } else {
      local_pose = predicted;
    }
  }
  auto node = std::make_shared<TrajectoryNode>(newest);
  node->step = local_pose.relativeTo(previous.pose);
  node->information = info.rotated(previous.pose.theta);
  best.trajectory = node;
  chain.back() = node.get();

  PoseEdge edge;
  const bool found = loop_closer_.find(chain, loops_, &edge, &report->loop);
  if (!found) return;
  loops_.push_back(edge);
  closeLoop(chain, report);
}

double ParticleFilter::dispersion() const {
  // How much the matches' corrections scatter beyond what prediction and match covariance
  // allow (mean normalised innovation square over its expectation), never below 1.
  return nis_expected_ > 0.0 ? std::max(1.0, nis_sum_ / nis_expected_) : 1.0;
}

OdometryScale ParticleFilter::significantScale(const Particle& p) const {
  // A learnt scale enters the prediction once it differs from 1 by more than 1.96 sd
  // (two-sided 5 %) of its estimate, the sd inflated by the matches' dispersion: where the data
  // say odometry's scale is 1, odometry is taken as it is.
  const double phi = dispersion();
  OdometryScale s = p.scale;
  if (std::fabs(p.scale.distance - 1.0) <= 1.96 * std::sqrt(phi * p.covariance.m[3][3]))
    s.distance = 1.0;
  if (std::fabs(p.scale.rotation - 1.0) <= 1.96 * std::sqrt(phi * p.covariance.m[4][4]))
    s.rotation = 1.0;
  return s;
}

void ParticleFilter::closeLoop(const std::vector<const TrajectoryNode*>& chain,
                               UpdateReport* report) {
  PoseGraph graph;
  for (const TrajectoryNode* n : chain) graph.addNode(n->pose);
  for (std::size_t k = 1; k < chain.size(); ++k)
    graph.addEdge({static_cast<int>(k) - 1, static_cast<int>(k), chain[k]->step,
                   chain[k]->information});
  for (const PoseEdge& e : loops_)
    if (e.to < graph.size()) graph.addEdge(e);
  graph.optimize(10);
  double moved = 0.0;
  for (std::size_t k = 0; k < chain.size(); ++k)
    moved = std::max(moved, std::hypot(graph.pose(int(k)).x - chain[k]->pose.x,
                                       graph.pose(int(k)).y - chain[k]->pose.y));
  // Less than half a cell everywhere: the map would not change.
  if (moved < 0.5 * params_.delta) return;
  std::shared_ptr<const TrajectoryNode> last;
  GridMap map(params_.delta);
  for (std::size_t k = 0; k < chain.size(); ++k) {
    auto node = std::make_shared<TrajectoryNode>(*chain[k]);
    node->pose = graph.pose(static_cast<int>(k));
    node->parent = last;
    registerScan(&map, node->pose, *node->laser, *node->ranges, params_.matcher.max_range,
                 params_.matcher.max_urange);
    last = node;
  }
  for (auto& p : particles_) {
    p.pose = last->pose;
    p.map = map;
    p.trajectory = last;
    p.log_weight = p.weight_sum = 0.0;
    p.drift_xy2 = p.drift_theta2 = 0.0;
    for (int i = 0; i < kStates; ++i)
      for (int j = 0; j < kStates; ++j)
        if (i < 3 || j < 3) p.covariance.m[i][j] = 0.0;
  }
  report->map_rebuilt = true;
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
    auto root_node = std::make_shared<TrajectoryNode>();
    root_node->pose = odom;
    root_node->stamp = stamp;
    root_node->laser = sharedLaser(laser);
    root_node->ranges = std::make_shared<const Ranges>(ranges);
    const std::shared_ptr<const TrajectoryNode> root = root_node;
    for (auto& p : particles_) {
      p.pose = odom;
      p.map = first;
      p.trajectory = root;
      // Odometry's scales are known as well as the motion model knows a metre's travel
      // (srr, a fraction of the distance) and a radian's turn (stt).
      // The match's pulls along the step: unknown (sd 1: end points in unmapped space may pull
      // the match back by up to the whole step) and turn (sd lsigma per angularUpdate: a turn
      // may misplace the match by up to one observation's spread).
      const double turn_sd = params_.matcher.lsigma / std::max(1e-3, params_.angular_update);
      p.covariance =
          Covariance::diagonal(0, 0, 0, params_.motion.srr * params_.motion.srr,
                               params_.motion.stt * params_.motion.stt, 1.0, turn_sd * turn_sd);
    }
    initialized_ = true;
    last_odom_ = previous_odom_ = odom;
    previous_stamp_ = stamp;
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
  // The robot's speed at this scan, and the scan period, from the scans seen.
  const double dt = stamp - previous_stamp_;
  previous_stamp_ = stamp;
  if (dt > 0.0) {
    scan_period_ = scan_period_ > 0.0 ? 0.9 * scan_period_ + 0.1 * dt : dt;
    speed_ = step.x / dt;
    turn_rate_ = step.theta / dt;
  }
  const bool due = linear_distance_ >= params_.linear_update ||
                   angular_distance_ >= params_.angular_update ||
                   (params_.temporal_update >= 0.0 &&
                    stamp - last_update_stamp_ > params_.temporal_update);
  if (!due) return report;

  const ScanPoints points = matcher_.matchPoints(laser, ranges);
  const Pose2 inc = odom.relativeTo(last_odom_);
  const OdometryPrior increment_prior = odometryPrior(inc);
  double best_score = -1.0;
  double mean_range = 0.0;
  for (const auto& q : points.points) mean_range += q.beams * std::hypot(q.hx, q.hy);
  mean_range = points.beams > 0.0 ? mean_range / points.beams : 0.0;
  // Each particle's match's NIS against its own prediction (NaN: no match), for the weights.
  std::vector<double> match_nis(particles_.size(), std::numeric_limits<double>::quiet_NaN());
  for (auto& p : particles_) {
    // Odometry's increment as this particle's estimate of its scales corrects it.
    const OdometryScale applied = significantScale(p);
    const Pose2 predicted = predict(p.pose, inc, applied);
    // The match's prior: this increment's spread plus what odometry may have drifted since a
    // scan last placed the particle (variances add).
    const OdometryPrior prior{
        std::sqrt(increment_prior.sigma_xy * increment_prior.sigma_xy + p.drift_xy2),
        std::sqrt(increment_prior.sigma_theta * increment_prior.sigma_theta + p.drift_theta2)};
    // The pose's covariance relative to the map, carried forward and grown by the increment.
    const Covariance predicted_covariance =
        propagate(p.covariance, p.pose, inc, increment_prior.sigma_xy * increment_prior.sigma_xy,
                  increment_prior.sigma_theta * increment_prior.sigma_theta, applied);
    // gmapping's proposal: the match climbs from a sample of the motion model (its noise about
    // the unscaled prediction, applied to the scaled one).
    const Pose2 sample =
        predicted * (p.pose * inc).inverse() * motion_.sample(p.pose, last_odom_, odom, rng_);
    matcher_.prepare(p.map, sample, points);
    Pose2 corrected;
    double score = matcher_.optimizeFrom(sample, predicted, points, &corrected, prior);
    if (score <= params_.minimum_score && points.beams > params_.minimum_score &&
        points.points.size() >= 3)
      score = rescue(p.map, predicted, points, prior, score, &corrected);
    if (score > params_.minimum_score) {
      // The match, weighed per map cell, against the prediction and its carried covariance.
      // The match's own pulls act along the step (the heading for a turn on the spot), with
      // the step's length times the share of end points in space the particle's map has not
      // seen, and with its turn.
      MatchBiasRegressors regressors;
      const double c = std::cos(p.pose.theta), s = std::sin(p.pose.theta);
      const double tx = c * inc.x - s * inc.y, ty = s * inc.x + c * inc.y;
      const double len = std::hypot(tx, ty);
      regressors.ux = len > 1e-6 ? tx / len : std::cos(predicted.theta);
      regressors.uy = len > 1e-6 ? ty / len : std::sin(predicted.theta);
      int matched = 0, contradicting = 0;
      matcher_.agreement(predicted, points, &matched, &contradicting);
      const double n = std::max<double>(1.0, static_cast<double>(points.points.size()));
      regressors.unknown_step = len * (1.0 - (matched + contradicting) / n);
      regressors.turn = std::fabs(inc.theta);
      std::pair<double, double> consistency;
      p.pose = fuse(predicted, predicted_covariance, corrected,
                    matcher_.calibratedInformation(corrected, points), &p.covariance, &p.scale,
                    &consistency, &regressors);
      match_nis[static_cast<std::size_t>(&p - particles_.data())] = consistency.first;
      nis_sum_ += consistency.first;
      nis_expected_ += consistency.second;
      p.drift_xy2 = p.drift_theta2 = 0.0;
      p.placed = true;
    } else {
      // No usable match: odometry's prediction, not a random sample of its spread (nothing
      // would tell the samples apart), and the spread is carried to the next match.
      ++report.failed_matches;
      p.pose = predicted;
      p.covariance = predicted_covariance;
      p.drift_xy2 = prior.sigma_xy * prior.sigma_xy;
      p.drift_theta2 = prior.sigma_theta * prior.sigma_theta;
      // Its scan is drawn if the pose is known to a cell at the scan's typical range, or if
      // most of the scan ends in space the map has never seen: a scan into new territory (open
      // floor, a new aisle) extends the map at odometry's pose, the best there is; not drawing
      // it would leave nothing to match the next scans against (in open space no match would
      // ever succeed again) while the drift only grows. A scan that mostly overlaps the map
      // would blur it at an uncertain pose and is left out.
      int matched = 0, contradicting = 0;
      matcher_.prepare(p.map, predicted, points);
      matcher_.agreement(predicted, points, &matched, &contradicting);
      p.placed = prior.sigma_xy + prior.sigma_theta * mean_range <= params_.delta ||
                 2 * (matched + contradicting) <= static_cast<int>(points.points.size());
    }
    p.information = matcher_.information(p.pose, points, prior);
    double sc = 0.0;
    const double l = matcher_.likelihood(p.pose, points, &sc);
    p.log_weight += l;
    p.weight_sum += l;
    best_score = std::max(best_score, score);
  }

  // gmapping's weight is the scan's likelihood at the match; the improved proposal's weight
  // is that likelihood integrated over the motion model, which also asks how probable the
  // match is under the particle's prediction. In a maze a corridor turned 90 degrees fits the
  // scan as well as the right one, and only that tells them apart. The factor is a calibrated
  // probability: weights()' tempering of the per-beam likelihood (1 / (ogain N)) is undone.
  const std::vector<double> evidence = relativeMatchEvidence(match_nis);
  const double untempered = params_.ogain * double(particles_.size());
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    particles_[i].log_weight += evidence[i] * untempered;
    particles_[i].weight_sum += evidence[i] * untempered;
  }
  const std::vector<double> w = weights();
  double sum_sq = 0.0;
  for (double x : w) sum_sq += x * x;
  report.neff = 1.0 / sum_sq;
  if (report.neff < params_.resample_threshold * double(particles_.size())) {
    resample(w);
    report.resampled = true;
  }
  const std::shared_ptr<const LaserGeometry> shared_laser = sharedLaser(laser);
  const auto shared_ranges = std::make_shared<const Ranges>(ranges);
  for (auto& p : particles_) {
    if (p.placed)
      registerScan(&p.map, p.pose, laser, ranges, params_.matcher.max_range,
                   params_.matcher.max_urange);
    auto node = std::make_shared<TrajectoryNode>();
    node->pose = p.pose;
    node->stamp = stamp;
    node->parent = p.trajectory;
    node->index = p.trajectory->index + 1;
    node->laser = shared_laser;
    node->ranges = shared_ranges;
    node->step = p.pose.relativeTo(p.trajectory->pose);
    node->information = p.information.rotated(p.trajectory->pose.theta);
    p.trajectory = node;
  }
  if (params_.loop_closure) backEnd(points, increment_prior, &report);

  last_odom_ = odom;
  last_update_speed_ = speed_;
  last_update_turn_rate_ = turn_rate_;
  linear_distance_ = angular_distance_ = 0.0;
  last_update_stamp_ = stamp;
  report.processed = true;
  report.update_index = updates_++;
  report.best_score = best_score;
  report.best_pose = best().pose;
  return report;
}

}  // namespace gmapping_lite
