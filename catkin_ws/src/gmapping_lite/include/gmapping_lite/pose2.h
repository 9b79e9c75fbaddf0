// The planar pose the filter works in: rosbook_env's Pose2, shared with amcl_lite.
#pragma once

#include <rosbook_env/pose2.h>

namespace gmapping_lite {

using rosbook_env::normalizeAngle;
using rosbook_env::Pose2;

}  // namespace gmapping_lite
