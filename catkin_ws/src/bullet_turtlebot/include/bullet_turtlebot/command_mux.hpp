// The Turtlebot's velocity path without ROS: a priority mux with per-input timeouts
// (yocs cmd_vel_mux) in front of a base that stops when commands stop (Kobuki watchdog),
// and validation that rejects NaN/inf/huge commands.
#pragma once

#include <string>
#include <vector>

namespace bullet_turtlebot {

struct MuxInput {
  std::string name;
  int priority = 0;
  double timeout = 1.0;  // s
};

// The contract's inputs: safety_controller (10, 0.2 s), teleop (7, 1.0 s), navi (5, 1.0 s).
std::vector<MuxInput> turtlebot_mux_inputs();

class CommandMux {
 public:
  explicit CommandMux(std::vector<MuxInput> inputs);
  // A message on input `index` at time `now`: true when it reaches the base (no live input
  // of higher priority).
  bool offer(int index, double now);
  // The input that currently owns the base, or -1.
  int active(double now) const;
  const std::vector<MuxInput>& inputs() const { return inputs_; }

 private:
  std::vector<MuxInput> inputs_;
  std::vector<double> last_;  // time of the last message per input, -inf when none
};

enum class CommandCheck { kOk, kNotFinite, kTooLarge };

// Every component must be finite; |linear| <= huge_linear and |angular| <= huge_angular.
CommandCheck check_command(const double linear[3], const double angular[3], double huge_linear,
                           double huge_angular);

}  // namespace bullet_turtlebot
