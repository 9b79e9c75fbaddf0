// The simulator is the clock: its own ROS time is set where it publishes /clock, not by
// roscpp's subscription to that /clock.
#pragma once

#include <ros/time.h>

#include <string>
#include <vector>

namespace bullet_turtlebot {

// Under /use_sim_time roscpp subscribes every node to /clock, this one included: each of the
// 100 messages per sim second it publishes would then cross two more of its threads (the
// poll thread that hands an intraprocess message over, the internal queue that sets the
// time), over a third of the node's CPU at speed 0. So roscpp is made to read /use_sim_time
// under another name, `kRoscppUseSimTime` (a remapping added to argv before ros::init; ROS
// remaps parameter names as it does topics), which nobody sets; the node reads the real one
// itself and, if it is true, sets its ROS time with each /clock it publishes (OwnClock::set).
constexpr const char* kRoscppUseSimTime = "~roscpp_use_sim_time";

// argv plus the remapping above (the last word wins, so it overrides a user's own remapping
// of /use_sim_time, which would change nothing else here). `storage` owns the added word.
std::vector<char*> argv_with_own_clock(int argc, char** argv, std::string* storage);

class OwnClock {
 public:
  // Reads /use_sim_time from the master (after ros::init; false if unset or unreachable).
  OwnClock();
  bool sim_time() const { return sim_time_; }
  // The node's ros::Time::now() becomes `now`, under sim time; nothing otherwise.
  void set(const ros::Time& now) const {
    if (sim_time_) ros::Time::setNow(now);
  }

 private:
  bool sim_time_ = false;
};

}  // namespace bullet_turtlebot
