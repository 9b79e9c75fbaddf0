#include "bullet_turtlebot/types.hpp"

#include <cmath>

namespace bullet_turtlebot {

double normalize_angle(double a) {
  a = std::fmod(a + M_PI, 2.0 * M_PI);
  if (a < 0) a += 2.0 * M_PI;
  return a - M_PI;
}

}  // namespace bullet_turtlebot
