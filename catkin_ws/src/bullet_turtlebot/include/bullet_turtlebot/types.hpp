// Plain value types shared by the ROS-free simulator core.
#pragma once

namespace bullet_turtlebot {

struct Pose2D {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;
};

struct Color {
  float r = 0.6f;
  float g = 0.6f;
  float b = 0.6f;
};

double normalize_angle(double a);

}  // namespace bullet_turtlebot
