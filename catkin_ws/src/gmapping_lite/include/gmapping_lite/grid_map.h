// An unbounded occupancy grid whose memory is shared between particles.
//
// The grid is split into square patches held by shared_ptr. Copying a GridMap copies only
// the patch pointers; a patch is cloned the first time a shared copy is written to
// (copy-on-write), so particles that descend from one ancestor share everything they have
// not re-observed since.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

namespace gmapping_lite {

// gmapping's PointAccumulator: how often a cell was crossed by a beam (visits), how often a
// beam ended in it (hits), and where inside the cell the hits fell (sum of offsets from the
// cell centre), so scan matching can use sub-cell positions.
struct Cell {
  float sum_dx = 0.0f;
  float sum_dy = 0.0f;
  uint32_t hits = 0;
  uint32_t visits = 0;

  // Occupancy probability, or -1 when never observed.
  double occupancy() const { return visits ? double(hits) / double(visits) : -1.0; }
};

struct CellIndex {
  int x = 0;
  int y = 0;
  bool operator==(const CellIndex& o) const { return x == o.x && y == o.y; }
};

class GridMap {
 public:
  static constexpr int kPatchBits = 5;
  static constexpr int kPatchSize = 1 << kPatchBits;  // cells per patch side

  explicit GridMap(double resolution = 0.05);

  double resolution() const { return resolution_; }

  // Cell containing a world point, and the centre of a cell.
  CellIndex toCell(double x, double y) const;
  void cellCentre(const CellIndex& c, double* x, double* y) const;

  // Read access: nullptr when the cell was never touched.
  const Cell* find(int ix, int iy) const;
  // The cells of patch (px, py) (row-major, kPatchSize per row), or nullptr if untouched.
  // Patch (px, py) covers cells [px * kPatchSize, (px + 1) * kPatchSize) in x, same in y.
  const Cell* patchCells(int px, int py) const;

  // Write access: allocates or un-shares the cell's patch as needed.
  Cell& edit(int ix, int iy);

  // Record one beam from (x0, y0) to (x1, y1): cells on the way become freer; the end
  // cell gets a hit at (x1, y1) when `hit`, else it is only visited.
  void traceBeam(double x0, double y0, double x1, double y1, bool hit);

  // Bounds (in cells, inclusive min / exclusive max) of all touched patches; false if empty.
  bool knownBounds(CellIndex* min, CellIndex* max) const;

  // Memory accounting for tests and diagnostics.
  std::size_t patchCount() const;
  std::size_t sharedPatchCount() const;  // patches also referenced by another map

 private:
  struct Patch {
    Cell cells[kPatchSize * kPatchSize];
  };
  using PatchPtr = std::shared_ptr<Patch>;

  // Patch table covers patch indices [px0, px0 + npx) x [py0, py0 + npy).
  PatchPtr* slot(int px, int py);
  const PatchPtr* slot(int px, int py) const;
  void growToInclude(int px, int py);
  // The writable cells of patch (px, py): allocated or un-shared as needed.
  Cell* editPatch(int px, int py);

  double resolution_;
  int px0_ = 0, py0_ = 0, npx_ = 0, npy_ = 0;
  std::vector<PatchPtr> patches_;
};

}  // namespace gmapping_lite
