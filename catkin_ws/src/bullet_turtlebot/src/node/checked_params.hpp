// Simulator parameters read and checked at the boundary: a value of the wrong type, not
// finite, or outside what the simulator can honour is a ParameterError naming the value and
// the fix, instead of a silent default or a simulator that quietly does something else.
#pragma once

#include <ros/node_handle.h>

#include <limits>
#include <stdexcept>
#include <string>

namespace bullet_turtlebot {

struct ParameterError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// ~name as a finite number in [lo, hi] (`fallback` when unset); `rule` says what is allowed,
// e.g. "a rate in (0, 100] Hz". Integers are accepted where a number is asked for.
double checked_number(const ros::NodeHandle& pnh, const std::string& name, double fallback, double lo,
                      double hi, const std::string& rule);

// The same for a whole number.
int checked_int(const ros::NodeHandle& pnh, const std::string& name, int fallback, int lo, int hi,
                const std::string& rule);

// ~name as a non-empty string (`fallback` when unset): a number or a boolean given where a
// name is asked for (`_world:=123`) is refused, not replaced by the fallback.
std::string checked_string(const ros::NodeHandle& pnh, const std::string& name, const std::string& fallback,
                           const std::string& rule);

// A lower bound that is not itself allowed (e.g. a rate above 0): the next double above `lo`.
inline double above(double lo) { return std::nextafter(lo, std::numeric_limits<double>::infinity()); }

}  // namespace bullet_turtlebot
