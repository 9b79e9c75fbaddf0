// Every tunable of the filter, named and defaulted as slam_gmapping's private parameters.
#pragma once

#include "gmapping_lite/motion_model.h"
#include "gmapping_lite/scan_matcher.h"

namespace gmapping_lite {

struct SlamParams {
  MatcherParams matcher;     // sigma, kernelSize, lstep, astep, iterations, lsigma, lskip,
                             // maxRange, maxUrange
  MotionNoise motion;        // srr, srt, str, stt
  double ogain = 3.0;        // smooths the likelihoods into weights
  double minimum_score = 0;  // below this match score, trust odometry
  int particles = 30;
  double resample_threshold = 0.5;
  double linear_update = 1.0;    // m travelled before a scan is processed
  double angular_update = 0.5;   // rad turned before a scan is processed
  double temporal_update = -1.0;  // s; <0 disables time-triggered updates
  double delta = 0.05;            // map resolution (m)
  double occ_thresh = 0.25;       // occupancy above this is published as occupied
  double xmin = -100, ymin = -100, xmax = 100, ymax = 100;  // initial map bounds
  unsigned seed = 42;
  // The pose-graph back end (not gmapping's; ~loop_closure). Off by default: measured on the
  // simulated and Stage recordings it made maps worse (false closures on a spin in place in
  // front of one wall, whose edges pin the pose along the wall), see issue 16.
  bool loop_closure = false;
};

}  // namespace gmapping_lite
