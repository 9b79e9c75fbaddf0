#include "gmapping_lite/occupancy.h"

#include <algorithm>
#include <cmath>

#include "rosbook_env/map_files.h"

namespace gmapping_lite {

OccupancyMap toOccupancy(const GridMap& map, double xmin, double ymin, double xmax, double ymax,
                         double occ_thresh) {
  const double res = map.resolution();
  CellIndex lo{static_cast<int>(std::floor(xmin / res + 1e-9)),
               static_cast<int>(std::floor(ymin / res + 1e-9))};
  CellIndex hi{static_cast<int>(std::ceil(xmax / res - 1e-9)),
               static_cast<int>(std::ceil(ymax / res - 1e-9))};
  CellIndex kmin, kmax;
  if (map.knownBounds(&kmin, &kmax)) {
    // Grow only as far as cells that were really observed, not whole patches.
    CellIndex omin = kmax, omax = kmin;
    for (int y = kmin.y; y < kmax.y; ++y)
      for (int x = kmin.x; x < kmax.x; ++x) {
        const Cell* c = map.find(x, y);
        if (!c || !c->visits) continue;
        omin = {std::min(omin.x, x), std::min(omin.y, y)};
        omax = {std::max(omax.x, x + 1), std::max(omax.y, y + 1)};
      }
    if (omin.x < omax.x) {
      lo = {std::min(lo.x, omin.x), std::min(lo.y, omin.y)};
      hi = {std::max(hi.x, omax.x), std::max(hi.y, omax.y)};
    }
  }
  OccupancyMap out;
  out.resolution = res;
  out.width = std::max(1, hi.x - lo.x);
  out.height = std::max(1, hi.y - lo.y);
  out.origin_x = lo.x * res;
  out.origin_y = lo.y * res;
  out.data.assign(static_cast<std::size_t>(out.width) * out.height, -1);
  if (!map.knownBounds(&kmin, &kmax)) return out;
  const int x0 = std::max(lo.x, kmin.x), x1 = std::min(lo.x + out.width, kmax.x);
  const int y0 = std::max(lo.y, kmin.y), y1 = std::min(lo.y + out.height, kmax.y);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const Cell* c = map.find(x, y);
      if (!c || !c->visits) continue;
      out.data[static_cast<std::size_t>(y - lo.y) * out.width + (x - lo.x)] =
          c->occupancy() > occ_thresh ? 100 : 0;
    }
  return out;
}

bool writeMapFiles(const OccupancyMap& map, const std::string& base, std::string* error) {
  rosbook_env::MapImage image;
  image.width = map.width;
  image.height = map.height;
  image.resolution = map.resolution;
  image.origin_x = map.origin_x;
  image.origin_y = map.origin_y;
  try {
    // The cells are -1, 0 or 100: map_saver's rule draws them 205, 254 and 0.
    image.pixels = rosbook_env::pixels_from_occupancy(map.data, map.width, map.height);
    rosbook_env::write_map_files(
        base, image, "CREATOR: gmapping_lite " + std::to_string(map.resolution) + " m/pix");
  } catch (const rosbook_env::MapFileError& e) {
    *error = e.what();
    return false;
  }
  return true;
}

}  // namespace gmapping_lite
