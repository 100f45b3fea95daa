#pragma once
/// \file
/// Where a world point lies relative to a posed hull.
#include "geometry/hull.h"

namespace mfz {

/// Signed Euclidean distance from `world_point` to the surface of `hull` at
/// `pose`: negative inside (minus the distance to the nearest face plane,
/// exact for a convex hull), positive outside (distance to the nearest face
/// polygon).
double signed_distance(const Hull& hull, const Pose& pose, const Vec3& world_point);

}  // namespace mfz
