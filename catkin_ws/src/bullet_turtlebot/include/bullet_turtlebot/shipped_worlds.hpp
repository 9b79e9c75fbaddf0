// Where the shipped worlds are: the package's worlds/ folder, found through ROS_PACKAGE_PATH, so
// the same binary works from the devel space and from an install space.
#pragma once

#include <ros/package.h>

#include <string>

namespace bullet_turtlebot {

inline std::string shipped_worlds_dir() {
  const std::string package = ros::package::getPath("bullet_turtlebot");
  return package.empty() ? std::string("worlds") : package + "/worlds";
}

}  // namespace bullet_turtlebot
