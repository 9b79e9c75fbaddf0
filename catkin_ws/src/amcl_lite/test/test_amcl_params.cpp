#include <gtest/gtest.h>

#include "amcl_lite/amcl_params.h"

using amcl_lite::AmclParams;
using amcl_lite::validate;

TEST(AmclParams, AmclDefaultsAreValid) {
  const AmclParams p;
  EXPECT_EQ(validate(p), "");
  EXPECT_EQ(p.min_particles, 100);
  EXPECT_EQ(p.max_particles, 5000);
  EXPECT_EQ(p.laser_max_beams, 30);
  EXPECT_DOUBLE_EQ(p.update_min_a, M_PI / 6.0);
  EXPECT_EQ(p.resample_interval, 2);
}

TEST(AmclParams, BadValuesAreNamedWithTheirRule) {
  AmclParams p;
  p.max_particles = 50;
  EXPECT_NE(validate(p).find("max_particles = 50"), std::string::npos) << validate(p);
  p = AmclParams();
  p.laser_sigma_hit = 0.0;
  EXPECT_NE(validate(p).find("laser_sigma_hit"), std::string::npos);
  p = AmclParams();
  p.kld_err = 1.5;
  EXPECT_NE(validate(p).find("kld_err"), std::string::npos);
  p = AmclParams();
  p.odom_alpha3 = -0.1;
  EXPECT_NE(validate(p).find("odom_alpha3"), std::string::npos);
  p = AmclParams();
  p.initial_pose_x = std::nan("");
  EXPECT_NE(validate(p).find("initial_pose_x"), std::string::npos);
  p = AmclParams();
  p.recovery_alpha_slow = 0.1;
  p.recovery_alpha_fast = 0.05;
  EXPECT_NE(validate(p).find("recovery_alpha_fast"), std::string::npos);
}

TEST(AmclParams, RefusesATransformToleranceAndAParticleCountItCannotHonour) {
  AmclParams p;
  p.transform_tolerance = std::nan("");  // ros::Duration(nan) would abort the node
  EXPECT_NE(validate(p).find("transform_tolerance"), std::string::npos) << validate(p);
  p.transform_tolerance = -1.0;
  EXPECT_NE(validate(p).find("transform_tolerance = -1"), std::string::npos) << validate(p);
  p = AmclParams();
  p.max_particles = 1000000000;  // the filter allocates this many at once
  EXPECT_NE(validate(p).find("max_particles = 1e+09"), std::string::npos) << validate(p);
  p.max_particles = amcl_lite::kMaxParticlesCap;
  EXPECT_EQ(validate(p), "");
}
