// The likelihood field a scan is matched against: for every cell of the part of one particle's
// map a match can touch, the nearest occupied cell's mean hit position, and where that cell
// lies on a straight wall, the wall's normal; plus what the map knows of the cell itself
// (never seen, seen free, occupied).
//
// Distances to wall cells are measured along the normal (point-to-line, the line reaching as
// far as the field's radius), so a scan that only partly overlaps the mapped part of a wall is
// not pulled back along the wall towards the mapped end: the bias point-to-point matching shows
// at every turn into new territory. The line does not reach into cells the map has seen free
// (a doorway beside a jamb): there the distance is to the hit point itself.
//
// A wall seen from one side only has its normal pointing to that side, and a beam that would
// reach it from the other side contradicts the map (it passed through unseen wall or came
// from inside it): gmapping's "free cell in front of the hit" test, made exact by the normal.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "gmapping_lite/grid_map.h"

namespace gmapping_lite {

// One occupied cell: its mean hit position and, on a wall, the unit normal (else 0, 0).
// `sided`: the wall was seen from one side only, and the normal points to that side.
struct FieldSeed {
  float mx, my;
  float nx, ny;
  bool sided;
};

// What the map says of a beam's end point.
enum class EndState : uint8_t {
  kMatched,     // near an occupied cell, reached from its seen side: d2 is the distance
  kContradict,  // in space the map has seen free, or through a wall from its unseen side
  kUnknown,     // in space the map has never seen: no evidence either way
};

struct EndPoint {
  double d2;  // squared distance to the matched cell (to its wall's line), capped at radius^2
  EndState state;
  const FieldSeed* seed;  // the matched seed, else nullptr
  bool across;            // d2 was measured along the seed's normal (point-to-line)
};

class MatchField {
 public:
  struct Point {
    double x, y;
  };

  // Prepare the field for queries within `reach` of the `focus` points (world coordinates):
  // occupied cells are those above `fullness`; distances are capped at `radius`. Only blocks
  // of cells near a focus point are computed, so the work follows the scan's end points
  // rather than the area their bounding box spans.
  void build(const GridMap& map, const std::vector<Point>& focus, double reach, double fullness,
             double radius);

  // The end point (x, y) of a beam travelling along the unit direction (ux, uy).
  EndPoint query(double x, double y, double ux, double uy) const {
    const int i = static_cast<int>(std::floor(x * inv_res_)) - x0_;
    const int j = static_cast<int>(std::floor(y * inv_res_)) - y0_;
    if (i < 0 || j < 0 || i >= w_ || j >= h_) return {cap2_, EndState::kUnknown, nullptr, false};
    const std::size_t k = static_cast<std::size_t>(j) * w_ + i;
    const uint8_t st = state_[k];
    const int32_t n = nearest_[k];
    if (n >= 0) {
      const FieldSeed& s = seeds_[static_cast<std::size_t>(n)];
      const bool wall = s.nx != 0.0f || s.ny != 0.0f;
      if (!(wall && s.sided && ux * s.nx + uy * s.ny > 0.0)) {
        const double ex = x - s.mx, ey = y - s.my;
        const bool line = wall && st != kFree;
        double d2;
        if (line) {
          const double across = ex * s.nx + ey * s.ny;
          d2 = across * across;
        } else {
          d2 = ex * ex + ey * ey;
        }
        if (d2 < cap2_) return {d2, EndState::kMatched, &s, line};
      } else if (st == kOccupied) {
        return {cap2_, EndState::kContradict, nullptr, false};
      }
    }
    return {cap2_, st == kUnseen ? EndState::kUnknown : EndState::kContradict, nullptr, false};
  }

  // Squared distance from (x, y) to the nearest occupied cell (to its wall's line for wall
  // cells), capped at radius^2; direction and free space are not considered.
  double distance2(double x, double y) const {
    const FieldSeed* s = seedAt(x, y);
    return s ? std::min(cap2_, seedDistance2(*s, x, y)) : cap2_;
  }

  // The seed nearest to (x, y), or nullptr beyond the radius or outside the field.
  const FieldSeed* seedAt(double x, double y) const {
    const int i = static_cast<int>(std::floor(x * inv_res_)) - x0_;
    const int j = static_cast<int>(std::floor(y * inv_res_)) - y0_;
    if (i < 0 || j < 0 || i >= w_ || j >= h_) return nullptr;
    const int32_t k = nearest_[static_cast<std::size_t>(j) * w_ + i];
    return k < 0 ? nullptr : &seeds_[static_cast<std::size_t>(k)];
  }

  static double seedDistance2(const FieldSeed& s, double x, double y) {
    const double ex = x - s.mx, ey = y - s.my;
    if (s.nx == 0.0f && s.ny == 0.0f) return ex * ex + ey * ey;
    const double across = ex * s.nx + ey * s.ny;
    return across * across;
  }

  std::size_t seedCount() const { return seeds_.size(); }
  double cap2() const { return cap2_; }

 private:
  static constexpr int kBlockBits = 3;  // blocks of 8 x 8 cells; a patch holds whole blocks
  static constexpr int kBlock = 1 << kBlockBits;
  static constexpr uint8_t kUnseen = 0, kFree = 1, kOccupied = 2;

  void markBlocks(const std::vector<Point>& focus, double reach_cells);
  void gatherSeeds(const GridMap& map, double fullness);
  void estimateNormals(double res);
  void propagate(double res);
  bool blockMarked(int i, int j) const {
    return marked_[static_cast<std::size_t>(j >> kBlockBits) * bw_ + (i >> kBlockBits)] != 0;
  }
  uint8_t stateAt(double x, double y) const {
    const int i = static_cast<int>(std::floor(x * inv_res_)) - x0_;
    const int j = static_cast<int>(std::floor(y * inv_res_)) - y0_;
    if (i < 0 || j < 0 || i >= w_ || j >= h_) return kUnseen;
    return state_[static_cast<std::size_t>(j) * w_ + i];
  }

  int x0_ = 0, y0_ = 0, w_ = 0, h_ = 0;  // cells; x0_, y0_ and w_, h_ are whole blocks
  int bw_ = 0, bh_ = 0;                   // blocks
  std::vector<unsigned char> marked_;     // per block: within reach of a focus point
  double inv_res_ = 20.0, cap2_ = 0.25;
  std::vector<FieldSeed> seeds_;
  std::vector<int32_t> nearest_;  // per cell: index into seeds_, -1 for none
  std::vector<uint8_t> state_;    // per cell: kUnseen, kFree or kOccupied
  std::vector<int32_t> queue_;
  std::vector<float> best2_;  // scratch for the brushfire: each cell's best squared distance
};

}  // namespace gmapping_lite
