#include "geometry/hull_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/closest_point.h"

namespace mfz {

double signed_distance(const Hull& hull, const Pose& pose, const Vec3& world_point) {
  const Vec3 p = pose.to_local_direction(world_point - pose.position);
  double outside_most = -std::numeric_limits<double>::infinity();
  for (int f = 0; f < hull.face_count(); ++f)
    outside_most = std::max(outside_most, hull.face_normal(f).dot(p) - hull.face_offset(f));
  if (outside_most <= 0) return outside_most;
  double nearest_sq = std::numeric_limits<double>::infinity();
  Vec3 loop[kMaxLoopOnStack];
  for (int f = 0; f < hull.face_count(); ++f) {
    // Only faces whose plane the point is outside of can hold the nearest point.
    if (hull.face_normal(f).dot(p) - hull.face_offset(f) <= 0) continue;
    const int n = std::min(hull.face_size(f), kMaxLoopOnStack);
    for (int k = 0; k < n; ++k) loop[k] = hull.vertex(hull.face_vertex(f, k));
    nearest_sq = std::min(nearest_sq, (closest_point_on_polygon(p, loop, n, hull.face_normal(f)) - p).squaredNorm());
  }
  return std::sqrt(nearest_sq);
}

}  // namespace mfz
