#include "geometry/hull_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/closest_point.h"

namespace mfz {

// Outside, the nearest point lies on a face whose plane the point is
// outside of, in exact arithmetic. Rounding breaks that: a point on a face
// can sit 1e-13 outside a neighbour folded by 1e-14 and exactly on its own
// face's plane, and the neighbour's polygon is far. So the faces the point
// is outside of come first, then every other face whose plane is nearer
// than the best so far: a face's polygon is never nearer than its plane,
// and a face of the hull can never undercut the distance to the hull
// (manifuzz fuzz: a false on-surface of 0.3 on the built-in).
//
// A caller that asks only whether the distance exceeds `enough` has its
// answer from any one face polygon within `enough`: the hull's surface is
// never further than one of its faces. The face the point stands highest
// over is asked first; where it is further, every face is measured as
// above, and the minimum is the same whichever face was asked first.
namespace {

double distance_to_surface(const Hull& hull, const Pose& pose, const Vec3& world_point, double enough) {
  const Vec3 p = pose.to_local_direction(world_point - pose.position);
  // Each face's height over its plane is taken once, for all three passes
  // (taken in each, it was three fifths of the function, which the on-surface
  // and within-both-hulls checks made 7% of a fuzz execution); faces past
  // the buffer take theirs again, to the same bits.
  constexpr int kHeightsOnStack = 256;
  double heights[kHeightsOnStack];
  const auto plane_height = [&](int f) { return hull.face_normal(f).dot(p) - hull.face_offset(f); };
  const auto height = [&](int f) { return f < kHeightsOnStack ? heights[f] : plane_height(f); };
  double outside_most = -std::numeric_limits<double>::infinity();
  int highest_over = 0;
  for (int f = 0; f < hull.face_count(); ++f) {
    const double h = plane_height(f);
    if (f < kHeightsOnStack) heights[f] = h;
    if (h > outside_most) outside_most = h, highest_over = f;
  }
  if (outside_most <= 0) return outside_most;
  Vec3 loop[kMaxLoopOnStack];
  const auto polygon_distance = [&](int f) {
    const int n = std::min(hull.face_size(f), kMaxLoopOnStack);
    for (int k = 0; k < n; ++k) loop[k] = hull.vertex(hull.face_vertex(f, k));
    return (closest_point_on_polygon(p, loop, n, hull.face_normal(f)) - p).norm();
  };
  // The face asked first is not asked again: the minimum is the same.
  double nearest = std::numeric_limits<double>::infinity();
  const int asked_first = enough >= 0 ? highest_over : -1;
  if (asked_first >= 0) {
    nearest = polygon_distance(asked_first);
    if (nearest <= enough) return nearest;
  }
  for (const bool outside_pass : {true, false}) {
    for (int f = 0; f < hull.face_count(); ++f) {
      const double plane = height(f);
      if (f == asked_first || (outside_pass ? plane <= 0 : (plane > 0 || -plane >= nearest))) continue;
      nearest = std::min(nearest, polygon_distance(f));
    }
    if (outside_pass && nearest <= enough) return nearest;
  }
  return nearest;
}

}  // namespace

double signed_distance(const Hull& hull, const Pose& pose, const Vec3& world_point) {
  return distance_to_surface(hull, pose, world_point, -std::numeric_limits<double>::infinity());
}

double signed_distance_past(const Hull& hull, const Pose& pose, const Vec3& world_point, double allowed) {
  return distance_to_surface(hull, pose, world_point, allowed);
}

}  // namespace mfz
