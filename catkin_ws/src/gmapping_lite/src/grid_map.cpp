#include "gmapping_lite/grid_map.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace gmapping_lite {

namespace {
int patchOf(int cell) { return cell >> GridMap::kPatchBits; }  // floor for negatives too
int offsetIn(int cell) { return cell & (GridMap::kPatchSize - 1); }
}  // namespace

GridMap::GridMap(double resolution) : resolution_(resolution) {}

CellIndex GridMap::toCell(double x, double y) const {
  return {static_cast<int>(std::floor(x / resolution_)),
          static_cast<int>(std::floor(y / resolution_))};
}

void GridMap::cellCentre(const CellIndex& c, double* x, double* y) const {
  *x = (c.x + 0.5) * resolution_;
  *y = (c.y + 0.5) * resolution_;
}

const GridMap::PatchPtr* GridMap::slot(int px, int py) const {
  const int i = px - px0_, j = py - py0_;
  if (i < 0 || j < 0 || i >= npx_ || j >= npy_) return nullptr;
  return &patches_[static_cast<std::size_t>(j) * npx_ + i];
}

GridMap::PatchPtr* GridMap::slot(int px, int py) {
  return const_cast<PatchPtr*>(static_cast<const GridMap*>(this)->slot(px, py));
}

const Cell* GridMap::find(int ix, int iy) const {
  const PatchPtr* s = slot(patchOf(ix), patchOf(iy));
  if (!s || !*s) return nullptr;
  return &(*s)->cells[offsetIn(iy) * kPatchSize + offsetIn(ix)];
}

const Cell* GridMap::patchCells(int px, int py) const {
  const PatchPtr* s = slot(px, py);
  return s && *s ? (*s)->cells : nullptr;
}

void GridMap::growToInclude(int px, int py) {
  if (npx_ == 0) {
    // Start with some room around the first patch so early growth is rare.
    px0_ = px - 4;
    py0_ = py - 4;
    npx_ = npy_ = 9;
    patches_.assign(static_cast<std::size_t>(npx_) * npy_, nullptr);
    return;
  }
  // Grow by at least a quarter per side touched, so repeated growth stays amortised.
  int nx0 = px0_, ny0 = py0_, nx1 = px0_ + npx_, ny1 = py0_ + npy_;
  const int margin_x = std::max(2, npx_ / 4), margin_y = std::max(2, npy_ / 4);
  if (px < nx0) nx0 = px - margin_x;
  if (px >= nx1) nx1 = px + 1 + margin_x;
  if (py < ny0) ny0 = py - margin_y;
  if (py >= ny1) ny1 = py + 1 + margin_y;
  std::vector<PatchPtr> grown(static_cast<std::size_t>(nx1 - nx0) * (ny1 - ny0));
  for (int j = 0; j < npy_; ++j)
    for (int i = 0; i < npx_; ++i)
      grown[static_cast<std::size_t>(j + py0_ - ny0) * (nx1 - nx0) + (i + px0_ - nx0)] =
          std::move(patches_[static_cast<std::size_t>(j) * npx_ + i]);
  patches_ = std::move(grown);
  px0_ = nx0;
  py0_ = ny0;
  npx_ = nx1 - nx0;
  npy_ = ny1 - ny0;
}

Cell* GridMap::editPatch(int px, int py) {
  PatchPtr* s = slot(px, py);
  if (!s) {
    growToInclude(px, py);
    s = slot(px, py);
  }
  if (!*s) {
    *s = std::make_shared<Patch>();
  } else if (s->use_count() > 1) {
    *s = std::make_shared<Patch>(**s);  // copy on write
  }
  return (*s)->cells;
}

Cell& GridMap::edit(int ix, int iy) {
  return editPatch(patchOf(ix), patchOf(iy))[offsetIn(iy) * kPatchSize + offsetIn(ix)];
}

void GridMap::traceBeam(double x0, double y0, double x1, double y1, bool hit) {
  const CellIndex a = toCell(x0, y0), b = toCell(x1, y1);
  // Bresenham over cells from a to b, excluding b. The patch being written is looked up (and
  // un-shared) once per patch the beam enters, not once per cell: patches are heap objects,
  // so the pointer stays valid while the patch table grows.
  int x = a.x, y = a.y;
  const int dx = std::abs(b.x - a.x), dy = -std::abs(b.y - a.y);
  const int sx = a.x < b.x ? 1 : -1, sy = a.y < b.y ? 1 : -1;
  int err = dx + dy;
  int patch_x = patchOf(x), patch_y = patchOf(y);
  Cell* cells = editPatch(patch_x, patch_y);
  while (!(x == b.x && y == b.y)) {
    if (patchOf(x) != patch_x || patchOf(y) != patch_y) {
      patch_x = patchOf(x);
      patch_y = patchOf(y);
      cells = editPatch(patch_x, patch_y);
    }
    cells[offsetIn(y) * kPatchSize + offsetIn(x)].visits += 1;
    const int e2 = 2 * err;
    if (e2 >= dy) {
      err += dy;
      x += sx;
    }
    if (e2 <= dx) {
      err += dx;
      y += sy;
    }
  }
  Cell& end = edit(b.x, b.y);
  end.visits += 1;
  if (hit) {
    double cx, cy;
    cellCentre(b, &cx, &cy);
    end.hits += 1;
    end.sum_dx += static_cast<float>(x1 - cx);
    end.sum_dy += static_cast<float>(y1 - cy);
  }
}

bool GridMap::knownBounds(CellIndex* min, CellIndex* max) const {
  bool any = false;
  int minx = 0, miny = 0, maxx = 0, maxy = 0;
  for (int j = 0; j < npy_; ++j)
    for (int i = 0; i < npx_; ++i) {
      if (!patches_[static_cast<std::size_t>(j) * npx_ + i]) continue;
      const int px = px0_ + i, py = py0_ + j;
      if (!any) {
        minx = maxx = px;
        miny = maxy = py;
        any = true;
      }
      minx = std::min(minx, px);
      maxx = std::max(maxx, px);
      miny = std::min(miny, py);
      maxy = std::max(maxy, py);
    }
  if (!any) return false;
  *min = {minx * kPatchSize, miny * kPatchSize};
  *max = {(maxx + 1) * kPatchSize, (maxy + 1) * kPatchSize};
  return true;
}

std::size_t GridMap::patchCount() const {
  return static_cast<std::size_t>(
      std::count_if(patches_.begin(), patches_.end(), [](const PatchPtr& p) { return !!p; }));
}

std::size_t GridMap::sharedPatchCount() const {
  return static_cast<std::size_t>(std::count_if(
      patches_.begin(), patches_.end(), [](const PatchPtr& p) { return p && p.use_count() > 1; }));
}

}  // namespace gmapping_lite
