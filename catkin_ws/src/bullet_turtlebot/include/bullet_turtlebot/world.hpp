// The static world in Bullet: walls from the grid (merged into boxes), primitives, and an
// infinite floor at z = 0. Answers ray casts (sensors) and cylinder sweeps (the robot).
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "bullet_turtlebot/types.hpp"
#include "bullet_turtlebot/world_spec.hpp"

namespace bullet_turtlebot {

// A solid the sensors can see: an upright box (yaw only) or an upright cylinder.
struct Solid {
  enum Kind { kBox, kCylinder } kind = kBox;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double yaw = 0.0;                                       // boxes
  Eigen::Vector3d half = Eigen::Vector3d::Constant(0.5);  // box half extents; cylinder: (r, r, h/2)
  Color color;
};

struct RayHit {
  double distance = 0.0;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  Color color;
  int solid = -1;  // index into World::solids(), -1 for the floor
};

struct SweepResult {
  bool hit = false;
  double fraction = 1.0;                                  // of the requested motion that is free
  Eigen::Vector2d normal = Eigen::Vector2d::Zero();       // from the obstacle towards the robot
  Eigen::Vector2d contact = Eigen::Vector2d::Zero();      // contact point, world frame
};

class World {
 public:
  explicit World(const WorldSpec& spec);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  // Nearest hit along origin + t * dir (dir unit length) for 0 <= t <= max_distance.
  bool raycast(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double max_distance,
               RayHit* hit, bool include_floor = true) const;

  // Moves an upright cylinder (radius, height, bottom at `clearance`) from `from` to `to`.
  // Contacts the motion leaves (normal · motion >= 0) are ignored, so a robot touching a
  // wall can always back away.
  SweepResult sweep_cylinder(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double radius,
                             double height, double clearance) const;

  // Whether the cylinder at `at` penetrates any solid (start pose validation).
  bool cylinder_collides(const Eigen::Vector2d& at, double radius, double height, double clearance) const;

  const std::vector<Solid>& solids() const { return solids_; }
  // Axis-aligned bounds of all solids (x/y); zero when the world is empty.
  Eigen::Vector2d min_corner() const { return min_; }
  Eigen::Vector2d max_corner() const { return max_; }

 private:
  struct Bullet;
  std::vector<Solid> solids_;
  std::unique_ptr<Bullet> bullet_;
  Eigen::Vector2d min_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d max_ = Eigen::Vector2d::Zero();
};

// Exact ray/solid intersection (no Bullet); exposed for tests. Returns false on a miss or
// when the origin lies inside the solid.
bool intersect_solid(const Solid& solid, const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                     double max_distance, double* distance, Eigen::Vector3d* normal);

// Solids for a spec: merged grid boxes first, then boxes, then cylinders.
std::vector<Solid> build_solids(const WorldSpec& spec);

}  // namespace bullet_turtlebot
