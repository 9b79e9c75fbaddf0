#include "gmapping_lite/occupancy.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

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

namespace {
bool replaceFile(const std::string& path, const std::string& bytes, std::string* error) {
  const std::string tmp = path + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) {
      *error = "cannot write " + tmp;
      return false;
    }
    f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    f.flush();
    if (!f) {
      *error = "failed writing " + tmp;
      std::remove(tmp.c_str());
      return false;
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    *error = "cannot rename " + tmp + " to " + path;
    std::remove(tmp.c_str());
    return false;
  }
  return true;
}

std::string baseName(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}
}  // namespace

bool writeMapFiles(const OccupancyMap& map, const std::string& base, std::string* error) {
  std::string pgm = "P5\n# CREATOR: gmapping_lite " + std::to_string(map.resolution) +
                    " m/pix\n" + std::to_string(map.width) + " " + std::to_string(map.height) +
                    "\n255\n";
  const std::size_t header = pgm.size();
  pgm.resize(header + static_cast<std::size_t>(map.width) * map.height);
  for (int j = 0; j < map.height; ++j) {
    const int row = map.height - 1 - j;  // image row 0 is the map's top
    for (int i = 0; i < map.width; ++i) {
      const int8_t v = map.at(i, j);
      pgm[header + static_cast<std::size_t>(row) * map.width + i] =
          static_cast<char>(v < 0 ? 205 : (v >= 100 ? 0 : 254));
    }
  }
  char yaml[512];
  std::snprintf(yaml, sizeof(yaml),
                "image: %s.pgm\nresolution: %f\norigin: [%f, %f, 0.000000]\nnegate: 0\n"
                "occupied_thresh: 0.65\nfree_thresh: 0.196\n\n",
                baseName(base).c_str(), map.resolution, map.origin_x, map.origin_y);
  return replaceFile(base + ".pgm", pgm, error) && replaceFile(base + ".yaml", yaml, error);
}

}  // namespace gmapping_lite
