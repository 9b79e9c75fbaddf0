#include "bullet_turtlebot/command_mux.hpp"

#include <cmath>
#include <limits>

namespace bullet_turtlebot {

std::vector<MuxInput> turtlebot_mux_inputs() {
  return {{"safety_controller", 10, 0.2}, {"teleop", 7, 1.0}, {"navi", 5, 1.0}};
}

CommandMux::CommandMux(std::vector<MuxInput> inputs)
    : inputs_(std::move(inputs)), last_(inputs_.size(), -std::numeric_limits<double>::infinity()) {}

int CommandMux::active(double now) const {
  int best = -1;
  for (size_t i = 0; i < inputs_.size(); ++i) {
    if (now - last_[i] > inputs_[i].timeout) continue;
    if (best < 0 || inputs_[i].priority > inputs_[best].priority) best = static_cast<int>(i);
  }
  return best;
}

bool CommandMux::offer(int index, double now) {
  const int owner = active(now);
  if (owner >= 0 && owner != index && inputs_[owner].priority > inputs_[index].priority) return false;
  last_[index] = now;
  return true;
}

CommandCheck check_command(const double linear[3], const double angular[3], double huge_linear,
                           double huge_angular) {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(linear[i]) || !std::isfinite(angular[i])) return CommandCheck::kNotFinite;
  }
  for (int i = 0; i < 3; ++i) {
    if (std::abs(linear[i]) > huge_linear || std::abs(angular[i]) > huge_angular) return CommandCheck::kTooLarge;
  }
  return CommandCheck::kOk;
}

}  // namespace bullet_turtlebot
