// Small builders for test worlds.
#pragma once

#include "bullet_turtlebot/world_spec.hpp"

namespace bullet_turtlebot {
namespace testing_helpers {

// A world with one wall (a box) whose near face is at x = face_x, spanning y in [-5, 5].
inline WorldSpec wall_world(double face_x, double height = 1.0) {
  WorldSpec spec;
  BoxSpec wall;
  wall.pose = Pose2D{face_x + 0.5, 0.0, 0.0};
  wall.size_x = 1.0;
  wall.size_y = 10.0;
  wall.size_z = height;
  spec.boxes.push_back(wall);
  return spec;
}

}  // namespace testing_helpers
}  // namespace bullet_turtlebot
