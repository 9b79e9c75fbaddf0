#include "bullet_turtlebot/world.hpp"

#include <btBulletCollisionCommon.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "bullet_turtlebot/grid_boxes.hpp"

namespace bullet_turtlebot {
namespace {

btVector3 bt(const Eigen::Vector3d& v) { return btVector3(btScalar(v.x()), btScalar(v.y()), btScalar(v.z())); }

inline SolidView view_solid(const Solid& s, const Eigen::Vector3d& origin) {
  SolidView v;
  v.solid = &s;
  if (s.kind == Solid::kBox) {
    const double c = s.cos_yaw, sn = s.sin_yaw;
    const Eigen::Vector3d rel = origin - s.center;
    // World to box frame: rotate by -yaw. Axis-aligned, the rotation would multiply by exactly
    // 1 and 0, which changes at most the sign of a zero, and nothing below depends on it.
    v.aligned = c == 1.0 && sn == 0.0;
    v.o[0] = v.aligned ? rel.x() : c * rel.x() + sn * rel.y();
    v.o[1] = v.aligned ? rel.y() : -sn * rel.x() + c * rel.y();
    v.o[2] = rel.z();
  } else {
    const double r = s.half.x();
    const double bottom = s.center.z() - s.half.z();
    const double top = s.center.z() + s.half.z();
    v.o[0] = origin.x() - s.center.x();
    v.o[1] = origin.y() - s.center.y();
    v.o[2] = origin.z();
    v.c = v.o[0] * v.o[0] + v.o[1] * v.o[1] - r * r;
    v.inside = v.c <= 0 && origin.z() >= bottom && origin.z() <= top;
  }
  return v;
}

inline bool intersect_box(const SolidView& v, const Eigen::Vector3d& dir, double max_distance, double* distance,
                          Eigen::Vector3d* normal) {
  const Solid& s = *v.solid;
  const double c = s.cos_yaw, sn = s.sin_yaw;
  const double* o = v.o;
  const double d[3] = {v.aligned ? dir.x() : c * dir.x() + sn * dir.y(),
                       v.aligned ? dir.y() : -sn * dir.x() + c * dir.y(), dir.z()};
  double t_enter = -std::numeric_limits<double>::infinity();
  double t_exit = std::numeric_limits<double>::infinity();
  int axis = -1;
  double sign = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double h = s.half[i];
    if (std::abs(d[i]) < 1e-12) {
      if (o[i] < -h || o[i] > h) return false;
      continue;
    }
    double t1 = (-h - o[i]) / d[i];
    double t2 = (h - o[i]) / d[i];
    if (t1 > t2) std::swap(t1, t2);
    if (t1 > t_enter) {
      t_enter = t1;
      axis = i;
      sign = d[i] > 0 ? -1.0 : 1.0;
    }
    if (t2 < t_exit) t_exit = t2;
    if (t_enter > t_exit) return false;
  }
  if (axis < 0 || t_enter < 0.0 || t_enter > max_distance) return false;  // inside, behind or far
  *distance = t_enter;
  Eigen::Vector3d local = Eigen::Vector3d::Zero();
  local[axis] = sign;
  *normal = Eigen::Vector3d(c * local.x() - sn * local.y(), sn * local.x() + c * local.y(), local.z());
  return true;
}

inline bool intersect_cylinder(const SolidView& v, const Eigen::Vector3d& dir, double max_distance,
                               double* distance, Eigen::Vector3d* normal) {
  if (v.inside) return false;
  const Solid& s = *v.solid;
  const double r = s.half.x();
  const double bottom = s.center.z() - s.half.z();
  const double top = s.center.z() + s.half.z();
  const double ox = v.o[0], oy = v.o[1], oz = v.o[2], c = v.c;
  double best = std::numeric_limits<double>::infinity();
  const double a = dir.x() * dir.x() + dir.y() * dir.y();
  if (a > 1e-12) {
    const double b = 2.0 * (ox * dir.x() + oy * dir.y());
    const double disc = b * b - 4 * a * c;
    if (disc >= 0) {
      const double t = (-b - std::sqrt(disc)) / (2 * a);
      const double z = oz + t * dir.z();
      if (t >= 0 && z >= bottom && z <= top) {
        best = t;
        *normal = Eigen::Vector3d((ox + t * dir.x()) / r, (oy + t * dir.y()) / r, 0.0);
      }
    }
  }
  for (const double cap : {top, bottom}) {
    if (std::abs(dir.z()) < 1e-12) break;
    const double t = (cap - oz) / dir.z();
    if (t < 0 || t >= best) continue;
    const double px = ox + t * dir.x(), py = oy + t * dir.y();
    if (px * px + py * py <= r * r) {
      best = t;
      *normal = Eigen::Vector3d(0, 0, cap == top ? 1.0 : -1.0);
    }
  }
  if (best > max_distance) return false;
  *distance = best;
  return true;
}

inline bool hit_view(const SolidView& v, const Eigen::Vector3d& dir, double max_distance, double* distance,
                     Eigen::Vector3d* normal) {
  return v.solid->kind == Solid::kBox ? intersect_box(v, dir, max_distance, distance, normal)
                                      : intersect_cylinder(v, dir, max_distance, distance, normal);
}

// intersect_solid, inlinable into the ray loops (the exported one is called through the PLT).
inline bool hit_solid(const Solid& solid, const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                      double max_distance, double* distance, Eigen::Vector3d* normal) {
  return hit_view(view_solid(solid, origin), dir, max_distance, distance, normal);
}

// Broadphase ray walk over Bullet's dynamic AABB tree, exact intersection per candidate.
struct RayWalker : public btBroadphaseRayCallback {
  const std::vector<Solid>* solids = nullptr;
  Eigen::Vector3d origin, dir;
  double best = 0.0;
  int best_index = -1;
  Eigen::Vector3d best_normal = Eigen::Vector3d::UnitZ();  // read only after a hit

  bool process(const btBroadphaseProxy* proxy) override {
    const auto* object = static_cast<const btCollisionObject*>(proxy->m_clientObject);
    const int index = object->getUserIndex();
    double t;
    Eigen::Vector3d n;
    if (hit_solid((*solids)[index], origin, dir, best, &t, &n) && t < best) {
      best = t;
      best_index = index;
      best_normal = n;
    }
    return true;
  }
};

// Closest sweep hit, ignoring contacts the motion leaves (so a touching robot can back off).
struct SweepCallback : public btCollisionWorld::ClosestConvexResultCallback {
  btVector3 motion;
  SweepCallback(const btVector3& from, const btVector3& to)
      : ClosestConvexResultCallback(from, to), motion(to - from) {}
  btScalar addSingleResult(btCollisionWorld::LocalConvexResult& result, bool normal_in_world) override {
    btVector3 n = normal_in_world ? result.m_hitNormalLocal
                                  : result.m_hitCollisionObject->getWorldTransform().getBasis() *
                                        result.m_hitNormalLocal;
    n.setZ(0);
    if (n.dot(motion) >= 0) return m_closestHitFraction;
    return ClosestConvexResultCallback::addSingleResult(result, normal_in_world);
  }
};

struct BoxCollector : public btBroadphaseAabbCallback {
  std::vector<int>* out;
  bool process(const btBroadphaseProxy* proxy) override {
    out->push_back(static_cast<const btCollisionObject*>(proxy->m_clientObject)->getUserIndex());
    return true;
  }
};

struct PenetrationCallback : public btCollisionWorld::ContactResultCallback {
  bool penetrating = false;
  btScalar addSingleResult(btManifoldPoint& cp, const btCollisionObjectWrapper*, int, int,
                           const btCollisionObjectWrapper*, int, int) override {
    if (cp.getDistance() < -1e-3) penetrating = true;
    return 0;
  }
};

}  // namespace

bool intersect_floor(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double best, RayHit* hit) {
  if (dir.z() >= -1e-12 || origin.z() <= 0) return false;
  const double t = -origin.z() / dir.z();
  if (t > best) return false;
  hit->distance = t;
  hit->normal = Eigen::Vector3d::UnitZ();
  hit->solid = -1;
  const Eigen::Vector3d p = origin + t * dir;
  const bool dark = (static_cast<long>(std::floor(p.x())) + static_cast<long>(std::floor(p.y()))) & 1;
  hit->color = dark ? Color{0.55f, 0.55f, 0.5f} : Color{0.68f, 0.68f, 0.62f};
  return true;
}

bool intersect_solid(const Solid& solid, const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                     double max_distance, double* distance, Eigen::Vector3d* normal) {
  return hit_solid(solid, origin, dir, max_distance, distance, normal);
}

std::vector<Solid> build_solids(const WorldSpec& spec) {
  std::vector<Solid> solids;
  const GridSpec& grid = spec.grid;
  if (grid.width > 0 && grid.height > 0) {
    const double res = grid.resolution;
    const double c = std::cos(grid.origin.yaw), s = std::sin(grid.origin.yaw);
    for (const CellRect& r : merge_cells(grid.occupied, grid.width, grid.height)) {
      // Image row 0 is the top of the map: y grows with decreasing row.
      const double mx = (r.col + r.width / 2.0) * res;
      const double my = (grid.height - r.row - r.height / 2.0) * res;
      Solid solid;
      solid.kind = Solid::kBox;
      solid.center = Eigen::Vector3d(grid.origin.x + c * mx - s * my, grid.origin.y + s * mx + c * my,
                                     spec.wall_height / 2);
      solid.yaw = grid.origin.yaw;
      solid.half = Eigen::Vector3d(r.width * res / 2, r.height * res / 2, spec.wall_height / 2);
      solid.color = spec.wall_color;
      solids.push_back(solid);
    }
  }
  for (const BoxSpec& b : spec.boxes) {
    Solid solid;
    solid.kind = Solid::kBox;
    solid.center = Eigen::Vector3d(b.pose.x, b.pose.y, b.size_z / 2);
    solid.yaw = b.pose.yaw;
    solid.half = Eigen::Vector3d(b.size_x / 2, b.size_y / 2, b.size_z / 2);
    solid.color = b.color;
    solids.push_back(solid);
  }
  for (const CylinderSpec& cyl : spec.cylinders) {
    Solid solid;
    solid.kind = Solid::kCylinder;
    solid.center = Eigen::Vector3d(cyl.x, cyl.y, cyl.height / 2);
    solid.half = Eigen::Vector3d(cyl.radius, cyl.radius, cyl.height / 2);
    solid.color = cyl.color;
    solids.push_back(solid);
  }
  for (Solid& s : solids) {
    s.cos_yaw = std::cos(s.yaw);
    s.sin_yaw = std::sin(s.yaw);
  }
  return solids;
}

struct World::Bullet {
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  btCollisionWorld world{&dispatcher, &broadphase, &config};
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<btCollisionObject>> objects;
};

World::World(const WorldSpec& spec) : solids_(build_solids(spec)), bullet_(std::make_unique<Bullet>()) {
  // Nothing here asks Bullet for overlapping pairs (all queries are ray, sweep, contact and
  // box tests against the tree), so pair finding on insertion is skipped: with tens of
  // thousands of touching wall boxes it was most of a large world's load time.
  bullet_->broadphase.m_deferedcollide = true;
  bool first = true;
  for (size_t i = 0; i < solids_.size(); ++i) {
    const Solid& s = solids_[i];
    std::unique_ptr<btCollisionShape> shape;
    if (s.kind == Solid::kBox) {
      shape = std::make_unique<btBoxShape>(bt(s.half));
    } else {
      shape = std::make_unique<btCylinderShapeZ>(bt(s.half));
    }
    auto object = std::make_unique<btCollisionObject>();
    btTransform pose;
    pose.setIdentity();
    pose.setOrigin(bt(s.center));
    pose.setRotation(btQuaternion(btVector3(0, 0, 1), btScalar(s.yaw)));
    object->setWorldTransform(pose);
    object->setCollisionShape(shape.get());
    object->setUserIndex(static_cast<int>(i));
    object->setCollisionFlags(btCollisionObject::CF_STATIC_OBJECT);
    bullet_->world.addCollisionObject(object.get(), btBroadphaseProxy::StaticFilter,
                                      btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);
    btVector3 lo, hi;
    shape->getAabb(pose, lo, hi);
    if (first) {
      min_ = Eigen::Vector2d(lo.x(), lo.y());
      max_ = Eigen::Vector2d(hi.x(), hi.y());
      first = false;
    } else {
      min_ = min_.cwiseMin(Eigen::Vector2d(lo.x(), lo.y()));
      max_ = max_.cwiseMax(Eigen::Vector2d(hi.x(), hi.y()));
    }
    bullet_->shapes.push_back(std::move(shape));
    bullet_->objects.push_back(std::move(object));
  }
  bullet_->world.updateAabbs();
  bullet_->broadphase.optimize();
}

World::~World() {
  for (auto& object : bullet_->objects) bullet_->world.removeCollisionObject(object.get());
}

bool World::raycast(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double max_distance,
                    RayHit* hit, bool include_floor) const {
  RayWalker walker;
  walker.solids = &solids_;
  walker.origin = origin;
  walker.dir = dir;
  walker.best = max_distance;
  for (int i = 0; i < 3; ++i) {
    walker.m_rayDirectionInverse[i] = dir[i] == 0.0 ? btScalar(BT_LARGE_FLOAT) : btScalar(1.0 / dir[i]);
    walker.m_signs[i] = walker.m_rayDirectionInverse[i] < 0.0;
  }
  walker.m_lambda_max = btScalar(max_distance);
  bullet_->broadphase.rayTest(bt(origin), bt(origin + dir * max_distance), walker);

  bool found = walker.best_index >= 0;
  if (found) {
    hit->distance = walker.best;
    hit->normal = walker.best_normal;
    hit->solid = walker.best_index;
    hit->color = solids_[walker.best_index].color;
  }
  if (include_floor && intersect_floor(origin, dir, walker.best, hit)) found = true;
  return found;
}

SweepResult World::sweep_cylinder(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double radius,
                                  double height, double clearance) const {
  SweepResult result;
  if ((to - from).squaredNorm() < 1e-18) return result;
  btCylinderShapeZ shape{btVector3(btScalar(radius), btScalar(radius), btScalar(height / 2))};
  const btScalar z = btScalar(clearance + height / 2);
  btTransform a, b;
  a.setIdentity();
  b.setIdentity();
  a.setOrigin(btVector3(btScalar(from.x()), btScalar(from.y()), z));
  b.setOrigin(btVector3(btScalar(to.x()), btScalar(to.y()), z));
  SweepCallback callback(a.getOrigin(), b.getOrigin());
  bullet_->world.convexSweepTest(&shape, a, b, callback);
  if (callback.hasHit()) {
    result.hit = true;
    result.fraction = callback.m_closestHitFraction;
    Eigen::Vector2d n(callback.m_hitNormalWorld.x(), callback.m_hitNormalWorld.y());
    if (n.norm() > 1e-9) n.normalize();
    result.normal = n;
    result.contact = Eigen::Vector2d(callback.m_hitPointWorld.x(), callback.m_hitPointWorld.y());
  }
  return result;
}

bool World::cylinder_collides(const Eigen::Vector2d& at, double radius, double height, double clearance) const {
  btCylinderShapeZ shape{btVector3(btScalar(radius), btScalar(radius), btScalar(height / 2))};
  btCollisionObject probe;
  btTransform pose;
  pose.setIdentity();
  pose.setOrigin(btVector3(btScalar(at.x()), btScalar(at.y()), btScalar(clearance + height / 2)));
  probe.setWorldTransform(pose);
  probe.setCollisionShape(&shape);
  PenetrationCallback callback;
  bullet_->world.contactTest(&probe, callback);
  return callback.penetrating;
}

}  // namespace bullet_turtlebot

namespace bullet_turtlebot {

std::vector<int> World::solids_in_box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) const {
  std::vector<int> out;
  BoxCollector collector;
  collector.out = &out;
  bullet_->broadphase.aabbTest(bt(lo), bt(hi), collector);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

namespace {

// Angular sector [lo, hi] (radians, relative to `centre`) a solid covers seen from `o`, and
// its horizontal distance; full circle when o is inside its footprint.
void solid_sector(const Solid& s, const Eigen::Vector2d& o, double* centre, double* lo, double* hi,
                  double* distance) {
  const Eigen::Vector2d c(s.center.x(), s.center.y());
  const Eigen::Vector2d rel = c - o;
  *centre = std::atan2(rel.y(), rel.x());
  if (s.kind == Solid::kCylinder) {
    const double d = rel.norm(), r = s.half.x();
    if (d <= r) {
      *lo = -M_PI;
      *hi = M_PI;
      *distance = 0.0;
      return;
    }
    *lo = -std::asin(r / d);
    *hi = -*lo;
    *distance = d - r;
    return;
  }
  // Box: corners, and the distance from o to the rectangle.
  const Eigen::Vector2d ax(s.cos_yaw, s.sin_yaw), ay(-s.sin_yaw, s.cos_yaw);
  const double lx = -rel.dot(ax), ly = -rel.dot(ay);  // o in the box frame
  const double ex = std::max(0.0, std::abs(lx) - s.half.x()), ey = std::max(0.0, std::abs(ly) - s.half.y());
  *distance = std::hypot(ex, ey);
  if (ex == 0.0 && ey == 0.0) {
    *lo = -M_PI;
    *hi = M_PI;
    return;
  }
  *lo = M_PI;
  *hi = -M_PI;
  for (const double sx : {-1.0, 1.0}) {
    for (const double sy : {-1.0, 1.0}) {
      const Eigen::Vector2d corner = rel + sx * s.half.x() * ax + sy * s.half.y() * ay;
      const double a = normalize_angle(std::atan2(corner.y(), corner.x()) - *centre);
      *lo = std::min(*lo, a);
      *hi = std::max(*hi, a);
    }
  }
}

// The part of the plane a fan's rays can reach: a circular sector (apex at the origin,
// azimuths yaw ± half_fov, radius max_distance), its bounding box, and a cheap conservative
// test on a solid's bounding circle.
struct FanWedge {
  Eigen::Vector2d apex, lo, hi;
  Eigen::Vector2d left, right;  // boundary directions at yaw + half_fov and yaw - half_fov
  double reach;
  bool narrow;  // under a half-plane: the wedge is the intersection of two half-planes

  FanWedge(const Eigen::Vector2d& o, double max_distance, double yaw, double half_fov)
      : apex(o),
        left(std::cos(yaw + half_fov), std::sin(yaw + half_fov)),
        right(std::cos(yaw - half_fov), std::sin(yaw - half_fov)),
        reach(max_distance),
        narrow(half_fov < M_PI / 2) {
    if (!narrow) {
      lo = o - Eigen::Vector2d::Constant(max_distance);
      hi = o + Eigen::Vector2d::Constant(max_distance);
      return;
    }
    lo = hi = o;
    for (const Eigen::Vector2d& p : {Eigen::Vector2d(o + max_distance * left), Eigen::Vector2d(o + max_distance * right)}) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    for (int quarter = -2; quarter <= 2; ++quarter) {  // the arc's extreme points along x and y
      const double a = quarter * M_PI / 2;
      if (std::abs(normalize_angle(a - yaw)) <= half_fov) {
        const Eigen::Vector2d p = o + max_distance * Eigen::Vector2d(std::cos(a), std::sin(a));
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
    }
  }

  bool may_hold(const Solid& s) const {
    const Eigen::Vector2d rel(s.center.x() - apex.x(), s.center.y() - apex.y());
    const double radius = s.kind == Solid::kCylinder ? s.half.x() : std::hypot(s.half.x(), s.half.y());
    if (rel.squaredNorm() > (reach + radius) * (reach + radius)) return false;
    if (!narrow) return true;
    const double beyond_left = left.x() * rel.y() - left.y() * rel.x();     // > 0: left of the left edge
    const double beyond_right = right.y() * rel.x() - right.x() * rel.y();  // > 0: right of the right edge
    return beyond_left <= radius && beyond_right <= radius;
  }
};

constexpr double kBinWidth = 0.5 * M_PI / 180.0;
constexpr double kAngleSlack = 1e-6;

}  // namespace

RayFan::RayFan(const World& world, const Eigen::Vector3d& origin, double max_distance, double yaw, double half_fov)
    : world_(world), origin_(origin), yaw_(yaw), half_fov_(std::min(half_fov, M_PI)), bin_width_(kBinWidth) {
  const int bins = std::max(1, static_cast<int>(std::ceil(2 * half_fov_ / bin_width_)) + 1);
  const FanWedge wedge(Eigen::Vector2d(origin.x(), origin.y()), max_distance, yaw_, half_fov_);
  const Eigen::Vector3d lo(wedge.lo.x(), wedge.lo.y(), -1e3);
  const Eigen::Vector3d hi(wedge.hi.x(), wedge.hi.y(), 1e3);
  std::vector<int> found = world.solids_in_box(lo, hi);
  struct Candidate {
    Entry entry;
    double centre, lo, hi;
  };
  std::vector<Candidate> list;
  list.reserve(found.size());
  const Eigen::Vector2d o(origin.x(), origin.y());
  for (int index : found) {
    // Most solids the bounding box holds lie outside the wedge: drop them before the
    // trigonometry below, which costs more than the rays that would test them.
    if (!wedge.may_hold(world.solids()[static_cast<size_t>(index)])) continue;
    Candidate c;
    c.entry.solid = index;
    c.entry.view = -1;  // set once it is kept
    solid_sector(world.solids()[index], o, &c.centre, &c.lo, &c.hi, &c.entry.min_distance);
    if (c.entry.min_distance > max_distance) continue;
    list.push_back(c);
  }
  std::sort(list.begin(), list.end(),
            [](const Candidate& a, const Candidate& b) { return a.entry.min_distance < b.entry.min_distance; });
  // Each candidate's bins: all of them, or up to two runs (its sector may wrap around once).
  // The bins are laid out one after another in one array (counted first, then filled in the
  // candidates' order, so each bin stays nearest first): two allocations per fan, not one
  // per bin.
  struct Runs {
    int first[2], last[2];
  };
  std::vector<Runs> runs(list.size());
  std::vector<std::uint32_t> count(static_cast<size_t>(bins) + 1, 0);
  const double start = yaw_ - half_fov_;
  for (size_t k = 0; k < list.size(); ++k) {
    const Candidate& c = list[k];
    Runs& r = runs[k];
    if (c.hi - c.lo >= 2 * M_PI - 1e-9) {
      r.first[0] = 0;
      r.last[0] = bins - 1;
      r.first[1] = 0;
      r.last[1] = -1;
    } else {
      // Sector in fan coordinates [0, 2 half_fov], clipped.
      const double a0 = normalize_angle(c.centre + c.lo - start - M_PI) + M_PI - kAngleSlack;
      const double span = c.hi - c.lo + 2 * kAngleSlack;
      for (int i = 0; i < 2; ++i) {
        const double s0 = a0 + (i == 0 ? 0.0 : -2 * M_PI), s1 = s0 + span;
        r.first[i] = std::max(0, static_cast<int>(std::floor(s0 / bin_width_)));
        r.last[i] = std::min(bins - 1, static_cast<int>(std::floor(s1 / bin_width_)));
      }
    }
    bool used = false;
    for (int i = 0; i < 2; ++i) {
      for (int b = r.first[i]; b <= r.last[i]; ++b) {
        ++count[static_cast<size_t>(b) + 1];
        used = true;
      }
    }
    candidates_ += used;
  }
  for (int b = 0; b < bins; ++b) count[static_cast<size_t>(b) + 1] += count[static_cast<size_t>(b)];
  entries_.resize(count[static_cast<size_t>(bins)]);
  bin_start_ = count;  // count[b] is now where bin b starts; it becomes the fill cursor below
  views_.reserve(list.size());
  for (size_t k = 0; k < list.size(); ++k) {
    const Runs& r = runs[k];
    Entry entry = list[k].entry;
    entry.view = static_cast<int>(views_.size());
    views_.push_back(view_solid(world.solids()[static_cast<size_t>(entry.solid)], origin_));
    for (int i = 0; i < 2; ++i) {
      for (int b = r.first[i]; b <= r.last[i]; ++b) entries_[count[static_cast<size_t>(b)]++] = entry;
    }
  }
}

int RayFan::bin_of(double azimuth) const {
  const double a = normalize_angle(azimuth - (yaw_ - half_fov_) - M_PI) + M_PI;
  return static_cast<int>(std::floor(a / bin_width_));
}

void RayFan::column_spans(int bin, const Eigen::Vector2d& dir, double max_s, std::vector<Span>* spans) const {
  spans->clear();
  if (bin < 0 || bin >= bins()) return;
  const auto& solids = world_.solids();
  for (const Entry* e_it = bin_begin(bin); e_it != bin_end(bin); ++e_it) {
    const Entry& e = *e_it;
    if (e.min_distance > max_s) break;
    const Solid& sol = solids[static_cast<size_t>(e.solid)];
    const double ox = origin_.x() - sol.center.x(), oy = origin_.y() - sol.center.y();
    Span span;
    span.solid = e.solid;
    span.z_lo = sol.center.z() - sol.half.z();
    span.z_hi = sol.center.z() + sol.half.z();
    if (sol.kind == Solid::kCylinder) {
      const double r = sol.half.x();
      const double b = ox * dir.x() + oy * dir.y();
      const double c = ox * ox + oy * oy - r * r;
      const double disc = b * b - c;
      if (disc < 0) continue;
      const double root = std::sqrt(disc);
      span.s_in = -b - root;
      span.s_out = -b + root;
      if (span.s_out < 0) continue;
      if (span.s_in < 0) continue;  // origin inside the footprint: treated as a miss, like raycast
      span.side_normal = Eigen::Vector2d((ox + span.s_in * dir.x()) / r, (oy + span.s_in * dir.y()) / r);
    } else {
      const double c = sol.cos_yaw, sn = sol.sin_yaw;
      const double o[2] = {c * ox + sn * oy, -sn * ox + c * oy};
      const double d[2] = {c * dir.x() + sn * dir.y(), -sn * dir.x() + c * dir.y()};
      double enter = -std::numeric_limits<double>::infinity(), exit = std::numeric_limits<double>::infinity();
      int axis = -1;
      double sign = 0.0;
      bool miss = false;
      for (int i = 0; i < 2 && !miss; ++i) {
        const double h = sol.half[i];
        if (std::abs(d[i]) < 1e-12) {
          miss = o[i] < -h || o[i] > h;
          continue;
        }
        double t1 = (-h - o[i]) / d[i], t2 = (h - o[i]) / d[i];
        if (t1 > t2) std::swap(t1, t2);
        if (t1 > enter) {
          enter = t1;
          axis = i;
          sign = d[i] > 0 ? -1.0 : 1.0;
        }
        exit = std::min(exit, t2);
        miss = enter > exit;
      }
      if (miss || axis < 0 || enter < 0) continue;
      span.s_in = enter;
      span.s_out = exit;
      const Eigen::Vector2d local = axis == 0 ? Eigen::Vector2d(sign, 0) : Eigen::Vector2d(0, sign);
      span.side_normal = Eigen::Vector2d(c * local.x() - sn * local.y(), sn * local.x() + c * local.y());
    }
    if (span.s_in > max_s) continue;
    spans->push_back(span);
  }
  std::sort(spans->begin(), spans->end(), [](const Span& a, const Span& b) { return a.s_in < b.s_in; });
}

bool RayFan::cast(const Eigen::Vector3d& dir, double max_distance, RayHit* hit, bool include_floor) const {
  return cast_in_bin(bin_of(std::atan2(dir.y(), dir.x())), dir, max_distance, hit, include_floor);
}

bool RayFan::cast_in_bin(int bin, const Eigen::Vector3d& dir, double max_distance, RayHit* hit,
                         bool include_floor) const {
  if (bin < 0 || bin >= bins()) {
    return world_.raycast(origin_, dir, max_distance, hit, include_floor);  // outside the fan
  }
  double best = max_distance;
  int best_index = -1;
  Eigen::Vector3d best_normal = Eigen::Vector3d::UnitZ();  // read only after a hit
  const auto& solids = world_.solids();
  Eigen::Vector3d n = Eigen::Vector3d::UnitZ();  // set by every hit
  for (const Entry* e_it = bin_begin(bin); e_it != bin_end(bin); ++e_it) {
    const Entry& e = *e_it;
    if (e.min_distance > best) break;
    double t;
    if (hit_view(views_[static_cast<size_t>(e.view)], dir, best, &t, &n) && t < best) {
      best = t;
      best_index = e.solid;
      best_normal = n;
    }
  }
  bool found = best_index >= 0;
  if (found) {
    hit->distance = best;
    hit->normal = best_normal;
    hit->solid = best_index;
    hit->color = solids[static_cast<size_t>(best_index)].color;
  }
  if (include_floor && intersect_floor(origin_, dir, best, hit)) found = true;
  return found;
}

}  // namespace bullet_turtlebot
