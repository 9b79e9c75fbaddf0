// Small builders for test worlds.
#pragma once

#include <stdlib.h>

#include <filesystem>
#include <stdexcept>
#include <string>

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

// A fresh directory under /tmp, removed with everything in it when the test ends (tests run
// on every build and CI run: they must not leave files behind).
class ScopedTempDir {
 public:
  explicit ScopedTempDir(const std::string& prefix) {
    std::string tmpl = "/tmp/" + prefix + "_XXXXXX";
    if (mkdtemp(tmpl.data()) == nullptr) throw std::runtime_error("mkdtemp failed for " + tmpl);
    path_ = tmpl;
  }
  ~ScopedTempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScopedTempDir(const ScopedTempDir&) = delete;
  ScopedTempDir& operator=(const ScopedTempDir&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace testing_helpers
}  // namespace bullet_turtlebot
