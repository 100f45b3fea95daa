#pragma once
/// \file
/// Closest points on simple shapes: shared by the generator's edge contacts,
/// the exact oracle's gap and the relations' comparison of contact sets.
#include "geometry/vec.h"

namespace mfz {

/// The longest face loop the distance queries copy onto the stack: every
/// vertex of a hull the harness takes (at most 1,024 points). A longer face,
/// handed in through the ABI, is measured by its first this many vertices.
/// At 512 the base of a 1,000-gon pyramid was measured as half of itself
/// (F61's hulls).
inline constexpr int kMaxLoopOnStack = 1024;

/// The point of segment [a, b] closest to p (a degenerate segment is a).
Vec3 closest_on_segment(const Vec3& p, const Vec3& a, const Vec3& b);
/// The point of triangle (a, b, c) closest to p, by Voronoi regions (Ericson,
/// Real-Time Collision Detection, 5.1.5); a degenerate triangle falls back to
/// its closest edge.
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

/// The closest points `on_1` of segment [p1, q1] and `on_2` of [p2, q2]
/// (Ericson, 5.1.9); parallel segments give one of the nearest pairs.
void closest_between_segments(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2, Vec3& on_1, Vec3& on_2);

/// The point of a planar convex polygon (loop of `count` points, unit normal
/// `normal`) closest to `p`: p's projection when it falls inside, else the
/// closest point of the boundary.
Vec3 closest_point_on_polygon(const Vec3& p, const Vec3* loop, int count, const Vec3& normal);

/// A ball about a polygon's centre whose points' projections pass every
/// edge of closest_point_on_polygon's inside test, with room for that
/// test's rounding: a point projected into it is inside without the test.
/// Worth its one pass over the loop where many points are measured against
/// one polygon (a cylinder's 60 contacts against its 64-gon cap tested 64
/// edges each, a tenth of the call).
struct PolygonCore {
  Vec3 centre = Vec3::Zero();
  double radius = -1;  ///< negative: no point is taken inside without the test
};
PolygonCore polygon_core(const Vec3* loop, int count, const Vec3& normal);
/// closest_point_on_polygon, to the bit, skipping the inside test for a
/// projection within `core` (of the same loop and normal).
Vec3 closest_point_on_polygon(const Vec3& p, const Vec3* loop, int count, const Vec3& normal, const PolygonCore& core);

}  // namespace mfz
