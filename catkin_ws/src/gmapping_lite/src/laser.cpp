#include "gmapping_lite/laser.h"

namespace gmapping_lite {

LaserGeometry LaserGeometry::planar(const Pose2& origin, double angle_min, double increment,
                                    int count) {
  LaserGeometry g;
  g.origin = origin;
  g.beams.resize(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) g.beams[i].angle = origin.theta + angle_min + i * increment;
  return g;
}

}  // namespace gmapping_lite
