// ScanPipeline, the scan path shared by slam_gmapping and slam_offline, over a real tf2
// buffer: what it does with good scans (the same as the filter fed by hand) and with each kind
// of scan it drops.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <geometry_msgs/TransformStamped.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2/LinearMath/Quaternion.h>
#include <tf2/buffer_core.h>
#include <tf2/utils.h>

#include "gmapping_lite/param_table.h"
#include "gmapping_lite/particle_filter.h"
#include "gmapping_lite/scan_input.h"
#include "gmapping_lite/scan_pipeline.h"
#include "synthetic.h"

using namespace gmapping_lite;  // NOLINT: test file

namespace {

constexpr double kStart = 100.0;  // s: the first scan's stamp (0 would mean "unstamped")

geometry_msgs::TransformStamped transform(const std::string& parent, const std::string& child,
                                          double stamp, double x, double y, double yaw,
                                          double roll = 0.0) {
  geometry_msgs::TransformStamped t;
  t.header.frame_id = parent;
  t.child_frame_id = child;
  t.header.stamp = ros::Time(stamp);
  t.transform.translation.x = x;
  t.transform.translation.y = y;
  tf2::Quaternion q;
  q.setRPY(roll, 0.0, yaw);
  t.transform.rotation.x = q.x();
  t.transform.rotation.y = q.y();
  t.transform.rotation.z = q.z();
  t.transform.rotation.w = q.w();
  return t;
}

sensor_msgs::LaserScan scanAt(double stamp, std::size_t beams = 11,
                              const std::string& frame = "laser") {
  sensor_msgs::LaserScan s;
  s.header.stamp = ros::Time(stamp);
  s.header.frame_id = frame;
  s.angle_min = -0.5f;
  s.angle_increment = 0.1f;
  s.angle_max = s.angle_min + s.angle_increment * float(beams - 1);
  s.range_min = 0.1f;
  s.range_max = 8.0f;
  s.ranges.assign(beams, 2.0f);
  return s;
}

// A buffer with the laser 0.1 m ahead of the base and odometry at rest from kStart to +10 s.
struct Fixture {
  tf2::BufferCore tf{ros::Duration(1000.0)};
  ScanPipelineOptions options;
  Fixture(bool with_mount = true) {
    if (with_mount) tf.setTransform(transform("base_link", "laser", 0, 0.1, 0, 0), "test", true);
    for (double t = kStart - 1.0; t <= kStart + 10.0; t += 0.5)
      tf.setTransform(transform("odom", "base_link", t, 0, 0, 0), "test");
    options.params.particles = 3;
  }
};

// The first scan, fed to a new pipeline over the fixture's buffer, is dropped as `expected`
// and counted once by `counter`, and no filter is made. Returns the problem it names.
std::string firstScanDropped(const sensor_msgs::LaserScan& scan, ScanResult expected,
                             int (ScanPipeline::*counter)() const) {
  Fixture f;
  ScanPipeline pipeline(f.options, lookupIn(f.tf));
  const ScanOutcome outcome = pipeline.process(scan);
  EXPECT_EQ(outcome.result, expected);
  EXPECT_EQ((pipeline.*counter)(), 1);
  EXPECT_EQ(pipeline.filter(), nullptr);
  return outcome.problem;
}

}  // namespace

TEST(ScanPipeline, PlacesScansAsTheFilterFedByHand) {
  // 8 s of the synthetic office tour, through tf and LaserScan messages.
  RunOptions run_options;
  run_options.beams = 200;
  const SyntheticRun run = simulateRun(SyntheticWorld::office(), officeTour(), run_options);
  const std::size_t steps = 80;
  ASSERT_GE(run.steps.size(), steps);
  const double increment = run.laser.beams[1].angle - run.laser.beams[0].angle;
  tf2::BufferCore tf{ros::Duration(1000.0)};
  tf.setTransform(transform("base_footprint", "scanner", 0, run.laser.origin.x,
                            run.laser.origin.y, 0),
                  "test", true);
  for (std::size_t i = 0; i < steps; ++i) {
    const SyntheticStep& s = run.steps[i];
    tf.setTransform(transform("odom", "base_footprint", kStart + s.stamp, s.odom.x, s.odom.y,
                              s.odom.theta),
                    "test");
  }
  ScanPipelineOptions options;
  options.base_frame = "/base_footprint";  // tf1's leading slash is ignored
  options.params.particles = 5;
  options.params.linear_update = 0.2;
  options.params.angular_update = 0.2;
  ScanPipeline pipeline(options, lookupIn(tf));

  // By hand: the beams from the mounting, ranges defaulted from range_max, odometry's yaw as
  // it comes back from a quaternion.
  SlamParams params = options.params;
  EXPECT_EQ(rangeDefaults(&params, run_options.range_max, false, false), "");
  ParticleFilter reference(params);
  LaserGeometry laser;
  std::string error;
  const float angle_min = float(run.laser.beams[0].angle);  // as a LaserScan holds them
  ASSERT_TRUE(makeLaserGeometry(tf2::Transform(tf2::Quaternion::getIdentity(),
                                               tf2::Vector3(run.laser.origin.x,
                                                            run.laser.origin.y, 0)),
                                angle_min, float(increment), run.laser.beams.size(), 0.1,
                                &laser, &error))
      << error;

  int updates = 0;
  for (std::size_t i = 0; i < steps; ++i) {
    const SyntheticStep& s = run.steps[i];
    sensor_msgs::LaserScan scan;
    scan.header.stamp = ros::Time(kStart + s.stamp);
    scan.header.frame_id = "scanner";
    scan.angle_min = angle_min;
    scan.angle_increment = float(increment);
    scan.angle_max = float(run.laser.beams.back().angle);
    scan.range_min = float(run_options.range_min);
    scan.range_max = float(run_options.range_max);
    scan.ranges = s.ranges;
    const ScanOutcome outcome = pipeline.process(scan);
    ASSERT_TRUE(outcome.problem.empty()) << outcome.problem;

    tf2::Quaternion q;
    q.setRPY(0, 0, s.odom.theta);
    const Pose2 odom(s.odom.x, s.odom.y, tf2::getYaw(q));
    const UpdateReport expected =
        reference.addScan(odom, scan.header.stamp.toSec(), laser,
                          toRanges(scan.ranges, scan.range_min, scan.range_max));
    ASSERT_EQ(outcome.update.processed, expected.processed) << "scan " << i;
    EXPECT_EQ(outcome.result,
              expected.processed ? ScanResult::kUpdated : ScanResult::kNotUpdated);
    EXPECT_NEAR(outcome.update.best_pose.x, expected.best_pose.x, 1e-9) << "scan " << i;
    EXPECT_NEAR(outcome.update.best_pose.y, expected.best_pose.y, 1e-9) << "scan " << i;
    EXPECT_NEAR(outcome.update.best_pose.theta, expected.best_pose.theta, 1e-9) << "scan " << i;
    updates += expected.processed;
  }
  EXPECT_GT(updates, 3);
  ASSERT_NE(pipeline.filter(), nullptr);
  EXPECT_EQ(pipeline.filter()->updates(), reference.updates());
  EXPECT_NEAR(pipeline.params().matcher.max_range, run_options.range_max - 0.01, 1e-6);
  EXPECT_EQ(pipeline.scans(), int(steps));
  EXPECT_EQ(pipeline.malformed() + pipeline.withoutOdometry() + pipeline.unstamped(), 0);
}

TEST(ScanPipeline, FirstPlacedScanMakesTheFilterAndSaysItsRanges) {
  Fixture f;
  ScanPipeline pipeline(f.options, lookupIn(f.tf));
  EXPECT_EQ(pipeline.filter(), nullptr);
  const ScanOutcome first = pipeline.process(scanAt(kStart));
  EXPECT_EQ(first.result, ScanResult::kUpdated);
  ASSERT_NE(pipeline.filter(), nullptr);
  std::string said;
  for (const ScanNote& note : first.notes) said += note.text + "\n";
  EXPECT_NE(said.find("laser 'laser' at (0.100, 0.000) in 'base_link', 11 beams"),
            std::string::npos)
      << said;
  EXPECT_NE(said.find("maxRange 7.99 m, maxUrange 7.99 m"), std::string::npos) << said;
  // The robot has not moved: placed, but no update; nothing said again.
  const ScanOutcome second = pipeline.process(scanAt(kStart + 0.1));
  EXPECT_EQ(second.result, ScanResult::kNotUpdated);
  EXPECT_TRUE(second.problem.empty());
  EXPECT_TRUE(second.notes.empty());
  EXPECT_EQ(pipeline.filter()->updates(), 1);
}

TEST(ScanPipeline, GivesTheFilterOdometrysPeriodFromTheNextScan) {
  Fixture f;
  ScanPipeline pipeline(f.options, lookupIn(f.tf));
  pipeline.process(scanAt(kStart));
  ASSERT_NE(pipeline.filter(), nullptr);
  EXPECT_EQ(pipeline.filter()->odometryPeriod(), 0.0);  // unknown: the scan period alone
  pipeline.setOdometryPeriod(0.02);
  pipeline.process(scanAt(kStart + 0.1));
  EXPECT_DOUBLE_EQ(pipeline.filter()->odometryPeriod(), 0.02);
}

TEST(ScanPipeline, HugeRangeMaxIsClampedWithAWarning) {
  Fixture f;
  ScanPipeline pipeline(f.options, lookupIn(f.tf));
  sensor_msgs::LaserScan scan = scanAt(kStart);
  scan.range_max = 1e30f;
  const ScanOutcome outcome = pipeline.process(scan);
  ASSERT_FALSE(outcome.notes.empty());
  bool warned = false;
  for (const ScanNote& note : outcome.notes)
    warned |= note.warning && note.text.find("beyond 80 m") != std::string::npos;
  EXPECT_TRUE(warned);
  EXPECT_NEAR(pipeline.params().matcher.max_range, 79.99, 1e-9);
}

TEST(ScanPipeline, UnstampedScanIsDroppedAndCounted) {
  const std::string problem =
      firstScanDropped(scanAt(0.0), ScanResult::kUnstamped, &ScanPipeline::unstamped);
  EXPECT_NE(problem.find("stamped 0"), std::string::npos) << problem;
}

TEST(ScanPipeline, MalformedScansAreCountedAndSaidOnceEveryFiveSeconds) {
  Fixture f;
  ScanPipeline pipeline(f.options, lookupIn(f.tf));
  std::vector<bool> said;
  for (int i = 0; i < 60; ++i) {  // 6 s at 10 Hz
    sensor_msgs::LaserScan scan = scanAt(kStart + 0.1 * i);
    scan.angle_increment = 0.0f;
    const ScanOutcome outcome = pipeline.process(scan);
    ASSERT_EQ(outcome.result, ScanResult::kMalformed);
    said.push_back(outcome.report);
    if (i == 0) {
      EXPECT_EQ(outcome.problem,
                "dropping a malformed scan on frame 'laser' at 100.000: angle_increment is 0: "
                "it must be a finite, non-zero angle between beams; malformed scans dropped "
                "so far: 1");
    }
  }
  EXPECT_EQ(pipeline.malformed(), 60);
  EXPECT_EQ(std::count(said.begin(), said.end(), true), 2);  // at 100 s and 105 s
  EXPECT_TRUE(said[0]);
  EXPECT_EQ(pipeline.filter(), nullptr);
  // A good scan after them is placed.
  EXPECT_EQ(pipeline.process(scanAt(kStart + 7.0)).result, ScanResult::kUpdated);
}

TEST(ScanPipeline, MissingMountNamesBothFramesUntilItAppears) {
  Fixture f(false);
  ScanPipeline pipeline(f.options, lookupIn(f.tf));
  const ScanOutcome outcome = pipeline.process(scanAt(kStart));
  EXPECT_EQ(outcome.result, ScanResult::kNoMount);
  EXPECT_NE(outcome.problem.find("no transform from base frame 'base_link' to laser frame "
                                 "'laser'"),
            std::string::npos)
      << outcome.problem;
  EXPECT_EQ(pipeline.withoutMount(), 1);
  f.tf.setTransform(transform("base_link", "laser", 0, 0.1, 0, 0), "test", true);
  EXPECT_EQ(pipeline.process(scanAt(kStart + 0.1)).result, ScanResult::kUpdated);
}

TEST(ScanPipeline, SteeplyTiltedMountIsRefusedUpsideDownIsMirrored) {
  Fixture f(false);
  f.tf.setTransform(transform("base_link", "tilted", 0, 0.1, 0, 0, 0.4), "test", true);
  f.tf.setTransform(transform("base_link", "flipped", 0, 0.1, 0, 0, M_PI), "test", true);
  ScanPipeline pipeline(f.options, lookupIn(f.tf));
  const ScanOutcome tilted = pipeline.process(scanAt(kStart, 11, "tilted"));
  EXPECT_EQ(tilted.result, ScanResult::kBadMount);
  EXPECT_NE(tilted.problem.find("laser frame 'tilted': the laser's scan plane is tilted 22.9"),
            std::string::npos)
      << tilted.problem;
  const ScanOutcome flipped = pipeline.process(scanAt(kStart, 11, "flipped"));
  EXPECT_EQ(flipped.result, ScanResult::kUpdated) << flipped.problem;
  ASSERT_FALSE(flipped.notes.empty());
  EXPECT_NE(flipped.notes[0].text.find("upside down"), std::string::npos);
}

TEST(ScanPipeline, NoOdometryAtTheScansStampIsNamedAndCounted) {
  const std::string problem = firstScanDropped(scanAt(kStart + 60.0),  // beyond the odometry
                                               ScanResult::kNoOdometry,
                                               &ScanPipeline::withoutOdometry);
  EXPECT_EQ(problem.rfind("no odometry: transform from 'odom' to 'base_link' at the scan's "
                          "stamp 160.000 is not available (",
                          0),
            0u)
      << problem;
  EXPECT_NE(problem.find("; 1 scans dropped so far"), std::string::npos) << problem;
}

TEST(ScanPipeline, ChangedBeamCountIsSaidOnceAndTheBeamsRebuilt) {
  Fixture f;
  ScanPipeline pipeline(f.options, lookupIn(f.tf));
  EXPECT_EQ(pipeline.process(scanAt(kStart, 11)).result, ScanResult::kUpdated);
  const ScanOutcome changed = pipeline.process(scanAt(kStart + 0.1, 7));
  EXPECT_TRUE(changed.problem.empty()) << changed.problem;
  ASSERT_FALSE(changed.notes.empty());
  EXPECT_TRUE(changed.notes[0].warning);
  EXPECT_NE(changed.notes[0].text.find("changed from 11 to 7 beams"), std::string::npos);
  EXPECT_TRUE(pipeline.process(scanAt(kStart + 0.2, 7)).notes.empty());
}
