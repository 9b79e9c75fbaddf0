// amcl's "diff" odometry motion model (Probabilistic Robotics, table 5.6): the odometry step
// split into rotate, translate, rotate, each perturbed by noise that grows with the motion.
#pragma once

#include <random>

#include "amcl_lite/pose2.h"

namespace amcl_lite {

struct OdomNoise {
  double alpha1 = 0.2, alpha2 = 0.2, alpha3 = 0.2, alpha4 = 0.2;
};

// `pose` moved by the odometry step old_odom -> new_odom, with sampled noise.
Pose2 sampleDiffMotion(const Pose2& pose, const Pose2& old_odom, const Pose2& new_odom,
                       const OdomNoise& noise, std::mt19937& rng);

}  // namespace amcl_lite
