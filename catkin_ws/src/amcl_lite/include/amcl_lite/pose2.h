// The planar pose the filter works in: rosbook_env's Pose2, shared with gmapping_lite.
#pragma once

#include <rosbook_env/pose2.h>

namespace amcl_lite {

using rosbook_env::normalizeAngle;
using rosbook_env::Pose2;

}  // namespace amcl_lite
