#include "oracles/hull_gap.h"

#include <algorithm>

#include "clip_polygon.h"
#include "closest_point.h"

namespace mfz {
namespace {

struct Nearest {
  double distance_sq = INFINITY;
  Vec3 on_a, on_b;
  void offer(const Vec3& a, const Vec3& b) {
    const double d = (b - a).squaredNorm();
    if (d < distance_sq) distance_sq = d, on_a = a, on_b = b;
  }
};

// The nearest point of each face polygon of `hull` to each of `points`. Every
// face, not only those whose plane the point lies outside of: at a touching
// case rounding puts a vertex a hair inside the face it touches, and that
// pair is the nearest. Each pair is a point of A and a point of B, so extra
// pairs can never undercut the gap.
template <class Offer>
void points_against_faces(const std::vector<Vec3>& points, const Hull& hull, const Pose& pose,
                          const std::vector<Vec3>& world, Offer&& offer) {
  Vec3 loop[kMaxPolygonVertices];
  for (int f = 0; f < hull.face_count(); ++f) {
    const Vec3 normal = pose.rotate(hull.face_normal(f));
    const int n = std::min(hull.face_size(f), kMaxPolygonVertices);
    for (int k = 0; k < n; ++k) loop[k] = world[hull.face_vertex(f, k)];
    for (const Vec3& p : points)
      offer(p, closest_point_on_polygon(p, loop, n, normal));
  }
}

}  // namespace

HullGap hull_gap(const Scene& s) {
  Nearest nearest;
  points_against_faces(s.world_a, s.hull_b, s.pose_b, s.world_b,
                       [&](const Vec3& on_a, const Vec3& on_b) { nearest.offer(on_a, on_b); });
  points_against_faces(s.world_b, s.hull_a, s.pose_a, s.world_a,
                       [&](const Vec3& on_b, const Vec3& on_a) { nearest.offer(on_a, on_b); });
  for (const HullEdge& ea : s.hull_a.edges())
    for (const HullEdge& eb : s.hull_b.edges()) {
      Vec3 on_a, on_b;
      closest_between_segments(s.world_a[ea.v0], s.world_a[ea.v1], s.world_b[eb.v0], s.world_b[eb.v1], on_a, on_b);
      nearest.offer(on_a, on_b);
    }
  return {std::sqrt(nearest.distance_sq), nearest.on_a, nearest.on_b};
}

}  // namespace mfz
