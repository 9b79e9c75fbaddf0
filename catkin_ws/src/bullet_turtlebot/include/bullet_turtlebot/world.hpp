// The static world in Bullet: walls from the grid (merged into boxes), primitives, and an
// infinite floor at z = 0. Answers ray casts (sensors) and cylinder sweeps (the robot).
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
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
  double cos_yaw = 1.0, sin_yaw = 0.0;                    // cached for ray tests
  Eigen::Vector3d half = Eigen::Vector3d::Constant(0.5);  // box half extents; cylinder: (r, r, h/2)
  Color color;
};

// What a solid's ray tests need from one ray origin, whatever the ray: a fan computes it once
// per solid instead of once per ray (RayFan), with the same arithmetic, so the same
// results as a single ray cast.
struct SolidView {
  const Solid* solid = nullptr;
  bool aligned = false;  // box: axis-aligned (every wall from the grid)
  bool inside = false;   // cylinder: the origin is inside it
  double o[3] = {0, 0, 0};  // box: the origin in its frame; cylinder: origin - centre in x, y, origin z
  double c = 0.0;           // cylinder: |(ox, oy)|^2 - r^2
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

class World;

// Where a vertical-sided solid lies along one horizontal direction from the fan's origin:
// horizontal distances [s_in, s_out], heights [z_lo, z_hi], the side's normal at s_in.
struct Span {
  double s_in = 0.0, s_out = 0.0;
  double z_lo = 0.0, z_hi = 0.0;
  Eigen::Vector2d side_normal = Eigen::Vector2d::Zero();
  int solid = -1;
};

// Many rays from one origin (a scan, a camera frame): Bullet's broadphase gathers the solids
// within reach once, then each ray tests only the solids whose horizontal angular sector
// (seen from the origin) contains its azimuth, nearest first, stopping early. Exact results,
// identical to World::raycast.
class RayFan {
 public:
  // Rays with azimuth within [yaw - half_fov, yaw + half_fov] reaching at most max_distance
  // (horizontally); other rays still work but may miss solids outside the sector.
  RayFan(const World& world, const Eigen::Vector3d& origin, double max_distance, double yaw, double half_fov);
  bool cast(const Eigen::Vector3d& dir, double max_distance, RayHit* hit, bool include_floor = true) const;
  // The same with the ray's azimuth bin known (bin_of(atan2(dir.y, dir.x))), e.g. per column.
  int bin_of(double azimuth) const;
  // The same for an azimuth given relative to the fan's yaw, within ±half_fov: no angle
  // wrapping, for rays at fixed angles from the sensor (a scan's beams).
  int bin_of_relative(double angle_from_yaw) const {
    return static_cast<int>(std::floor((angle_from_yaw + half_fov_) / bin_width_));
  }
  bool cast_in_bin(int bin, const Eigen::Vector3d& dir, double max_distance, RayHit* hit,
                   bool include_floor = true) const;
  size_t candidates() const { return candidates_; }
  // Every solid the horizontal ray from the origin along `dir` (unit, 2D) crosses within
  // max_s, sorted by s_in. A level camera's column shares this line, so its pixels can be
  // resolved from the spans with a few multiplications each (see render_depth).
  void column_spans(int bin, const Eigen::Vector2d& dir, double max_s, std::vector<Span>* spans) const;

 private:
  struct Entry {
    int solid;
    int view;             // index into views_
    double min_distance;  // horizontal distance from the origin to the solid's footprint
  };
  int bins() const { return static_cast<int>(bin_start_.size()) - 1; }
  const Entry* bin_begin(int bin) const { return entries_.data() + bin_start_[static_cast<size_t>(bin)]; }
  const Entry* bin_end(int bin) const { return entries_.data() + bin_start_[static_cast<size_t>(bin) + 1]; }

  const World& world_;
  Eigen::Vector3d origin_;
  double yaw_, half_fov_, bin_width_;
  std::vector<SolidView> views_;            // each candidate solid seen from the origin
  std::vector<Entry> entries_;              // per azimuth bin, nearest first, bin after bin
  std::vector<std::uint32_t> bin_start_;    // bin b is entries_[bin_start_[b], bin_start_[b + 1])
  size_t candidates_ = 0;
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
  // Indices of solids whose bounding boxes overlap the given box (Bullet broadphase).
  std::vector<int> solids_in_box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) const;
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

// Floor hit at z = 0 (a tiled floor), when the ray goes down and reaches it before `best`.
bool intersect_floor(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double best, RayHit* hit);

// Exact ray/solid intersection (no Bullet); exposed for tests. Returns false on a miss or
// when the origin lies inside the solid.
bool intersect_solid(const Solid& solid, const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                     double max_distance, double* distance, Eigen::Vector3d* normal);

// Solids for a spec: merged grid boxes first, then boxes, then cylinders.
std::vector<Solid> build_solids(const WorldSpec& spec);

}  // namespace bullet_turtlebot
