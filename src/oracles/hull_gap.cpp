#include "oracles/hull_gap.h"

#include <algorithm>
#include <cmath>

#include "geometry/closest_point.h"

namespace mfz {
namespace {

struct Nearest {
  double distance_sq = INFINITY;
  Vec3 on_a, on_b;
  void offer(const Vec3& a, const Vec3& b) {
    const double d = (b - a).squaredNorm();
    if (d < distance_sq) distance_sq = d, on_a = a, on_b = b;
  }
  // A pair of features whose bounding spheres (centres `c0`, `c1`, radii
  // summing to `radii`) lie further apart than the nearest pair so far, by
  // more than `rounding`, cannot come nearer: skipping it changes nothing
  // but the time (brute force over every pair was a tenth of a case).
  bool cannot_beat(const Vec3& c0, const Vec3& c1, double radii, double rounding) const {
    const double reach = radii + std::sqrt(distance_sq) + rounding;
    return (c1 - c0).squaredNorm() > reach * reach;
  }
};

// The nearest point of each face polygon of `hull` to each of `points`. Every
// face, not only those whose plane the point lies outside of: at a touching
// case rounding puts a vertex a hair inside the face it touches, and that
// pair is the nearest. Each pair is a point of A and a point of B, so extra
// pairs can never undercut the gap. `points_on_a` says which hull the points
// belong to.
void points_against_faces(const std::vector<Vec3>& points, bool points_on_a, const Hull& hull, const Pose& pose,
                          const std::vector<Vec3>& world, double rounding, Nearest& nearest) {
  Vec3 loop[kMaxLoopOnStack];
  for (int f = 0; f < hull.face_count(); ++f) {
    const Vec3 normal = pose.rotate(hull.face_normal(f));
    const int n = std::min(hull.face_size(f), kMaxLoopOnStack);
    Vec3 centre = Vec3::Zero();
    for (int k = 0; k < n; ++k) loop[k] = world[hull.face_vertex(f, k)], centre += loop[k];
    centre /= n;
    double radius = 0;
    for (int k = 0; k < n; ++k) radius = std::max(radius, (loop[k] - centre).norm());
    for (const Vec3& p : points) {
      if (nearest.cannot_beat(p, centre, radius, rounding)) continue;
      const Vec3 on_face = closest_point_on_polygon(p, loop, n, normal);
      if (points_on_a)
        nearest.offer(p, on_face);
      else
        nearest.offer(on_face, p);
    }
  }
}

struct Segment {
  Vec3 from, to, middle;
  double half_length;
  Segment(const Vec3& p, const Vec3& q) : from(p), to(q), middle(0.5 * (p + q)), half_length(0.5 * (q - p).norm()) {}
};

std::vector<Segment> segments_of(const Hull& hull, const std::vector<Vec3>& world) {
  std::vector<Segment> out;
  out.reserve(hull.edges().size());
  for (const HullEdge& e : hull.edges()) out.emplace_back(world[e.v0], world[e.v1]);
  return out;
}

}  // namespace

HullGap hull_gap(const Scene& s) {
  // The bounds are computed in world coordinates: allow their rounding.
  const double rounding = s.length_tolerance(0);
  Nearest nearest;
  points_against_faces(s.world_a, /*points_on_a=*/true, s.hull_b, s.pose_b, s.world_b, rounding, nearest);
  points_against_faces(s.world_b, /*points_on_a=*/false, s.hull_a, s.pose_a, s.world_a, rounding, nearest);
  const std::vector<Segment> edges_b = segments_of(s.hull_b, s.world_b);
  for (const Segment& ea : segments_of(s.hull_a, s.world_a))
    for (const Segment& eb : edges_b) {
      if (nearest.cannot_beat(ea.middle, eb.middle, ea.half_length + eb.half_length, rounding)) continue;
      Vec3 on_a, on_b;
      closest_between_segments(ea.from, ea.to, eb.from, eb.to, on_a, on_b);
      nearest.offer(on_a, on_b);
    }
  return {std::sqrt(nearest.distance_sq), nearest.on_a, nearest.on_b};
}

}  // namespace mfz
