// gmapping's odometry motion model: the odometry increment, perturbed by Gaussian noise whose
// spread grows with the distance travelled and the angle turned.
#pragma once

#include <random>

#include "gmapping_lite/pose2.h"

namespace gmapping_lite {

struct MotionNoise {
  // Used as gmapping's code uses them (its wiki swaps the wording of srt and str):
  double srr = 0.1;  // translation noise per metre travelled
  double srt = 0.2;  // rotation noise per metre travelled
  double str = 0.1;  // translation noise per radian turned
  double stt = 0.2;  // rotation noise per radian turned
};

class MotionModel {
 public:
  explicit MotionModel(const MotionNoise& noise) : noise_(noise) {}

  // A sample of where `pose` ends up after the odometry moved from old_odom to new_odom.
  Pose2 sample(const Pose2& pose, const Pose2& old_odom, const Pose2& new_odom,
               std::mt19937& rng) const;

 private:
  MotionNoise noise_;
};

}  // namespace gmapping_lite
