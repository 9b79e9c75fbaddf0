// Small builders for test worlds.
#pragma once

#include "bullet_turtlebot/world_spec.hpp"

namespace bullet_turtlebot {
namespace testing_helpers {

// A world with one box of the given footprint and height (BoxSpec's default 1 m).
inline WorldSpec box_world(const Pose2D& pose, double size_x, double size_y, double size_z = 1.0) {
  WorldSpec spec;
  BoxSpec box;
  box.pose = pose;
  box.size_x = size_x;
  box.size_y = size_y;
  box.size_z = size_z;
  spec.boxes.push_back(box);
  return spec;
}

// A world with one wall (a box) whose near face is at x = face_x, spanning y in [-5, 5].
inline WorldSpec wall_world(double face_x, double height = 1.0) {
  return box_world(Pose2D{face_x + 0.5, 0.0, 0.0}, 1.0, 10.0, height);
}

}  // namespace testing_helpers
}  // namespace bullet_turtlebot
