#include "generator/clip_polygon.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/closest_point.h"
#include "geometry/loop_corners.h"

namespace mfz {
namespace {

// Whether `foot`, on the side plane, lies along the side's edge, between its
// ends to within `slack`.
bool along_edge(const Vec3& foot, const SideEdge* edge, double slack) {
  if (!edge) return true;
  const Vec3 run = edge->to - edge->from;
  const double length = run.norm();
  if (!(length > 0)) return false;
  const double along = (foot - edge->from).dot(run) / length;
  return along >= -slack && along <= length + slack;
}

}  // namespace

bool clip_to_plane(const ClipPolygon& in, const Plane& plane, ClipPolygon& out, double on_plane, double near_plane,
                   const SideEdge* edge, double in_plane_sine, double in_plane_band, bool* held_in_plane) {
  out.clear();
  const int n = in.size();
  if (n <= 0) return true;
  double d[kMaxPolygonVertices];
  for (int k = 0; k < n; ++k) d[k] = plane.signed_distance(in[k]);
  // A point is inside within `on_plane`, or as an end of an edge that lies
  // in the plane to `in_plane_sine` of its length: both ends that near,
  // whatever the frame's rounding. Such an edge is kept whole, as it is in
  // a frame whose rounding covers its ends: interpolated, its crossing moves
  // by the ends' distances over its slope, anywhere along it. An edge
  // 14,000 long, tilted 1e-13 from a side plane, crossed it mid-edge at the
  // origin and was kept whole 1.8e8 out, and the contact at its crossing,
  // 4000 deep, was in one frame only (F53, far-from-origin, manifuzz fuzz
  // --strict, open as O19).
  const auto lies_in_plane = [&](int i, int j) {
    return std::max(std::abs(d[i]), std::abs(d[j])) <= in_plane_sine * (in[j] - in[i]).norm();
  };
  // Past `in_plane_band` (the caller's bound on the sine times any edge's
  // length) a point lies in no such edge: most outside points are, and are
  // told by one comparison (measuring their edges cost F53 1% of an 8-point
  // call).
  const auto inside = [&](int k) {
    if (d[k] <= on_plane) return true;
    const bool held =
        d[k] <= in_plane_band && (lies_in_plane(previous_corner(k, n), k) || lies_in_plane(k, next_corner(k, n)));
    if (held && held_in_plane) *held_in_plane = true;
    return held;
  };
  bool ok = true;
  Vec3 start = in[n - 1];
  double d_start = d[n - 1];
  bool start_crossing = in.is_crossing(n - 1);
  bool start_inside = inside(n - 1);
  for (int k = 0; k < n; ++k) {
    const Vec3& end = in[k];
    const double d_end = d[k];
    const bool end_crossing = in.is_crossing(k);
    const bool end_inside = inside(k);
    // An edge whose inside end is on the plane (within `on_plane`, either
    // side) crosses it there: that end is kept anyway. Interpolating would
    // divide rounding by rounding when the edge lies in the plane, and put
    // the crossing anywhere along it (F23). Within the band on the inside
    // as well as the outside: an end 1.8e-12 inside a band of 1.7e-10, its
    // edge 1e-8 out at the other end 13,000 along, was crossed 2.5 from it,
    // where the same end at 0 in the case's frame was its own crossing
    // (F48: a tetrahedron's edge in a side plane, tilted 1e-12; rigid-motion,
    // manifuzz check --strict --seed 2026112845).
    if (start_inside != end_inside) {
      // An outside end within `near_plane` crosses at its foot: interpolating
      // along an edge nearly in the plane moves the crossing by the end's
      // rounding over the edge's slope (F32: a corner 1.5e-12 out, its edge
      // 6e-7 rad off the plane, crossed 2.4e-6 along). Only where the foot
      // lies along the side's edge: past its end, by the sharp corner of a
      // sliver 3.1e-7 rad wide, each of the two sides took a point 6e-8 out
      // for one on it, and a contact stood 0.23 beyond the corner (F36).
      // Only a corner's rounding is the world's: a crossing an earlier plane
      // made lies on its edge, and its foot leaves the polygon. A needle's
      // edge, steep to the reference face, crossed one side 6.5e-8 past
      // where it left the other, inside that side's band; its foot stood
      // 6e-8 higher than the edge's true crossing, above the reference
      // plane, and the contact there was dropped or kept as the sides' order
      // went (vertex-order, 1e6 from the origin, --seed 2026112606). The
      // foot comes first whichever side of the plane the inside end rounds
      // to: with both ends within rounding of the plane, the edge lies in
      // it, and the outside end, inside in another frame, belongs to the
      // polygon.
      const Vec3& outside = start_inside ? end : start;
      const double d_outside = start_inside ? d_end : d_start;
      const double d_inside = start_inside ? d_start : d_end;
      const bool outside_is_corner = !(start_inside ? end_crossing : start_crossing);
      // An inside corner within `near_plane` is the edge's crossing, as an
      // outside one crosses at its foot: it carries the world's rounding
      // too, and so far in, interpolating along an edge nearly in the plane
      // moves the crossing by that rounding over the edge's slope. A
      // corner 9.4e-5 inside a side plane, 3.2e12 from the origin (the
      // world's rounding 0.046 there), its edge 9.6e-9 rad off the plane,
      // crossed 8658 along, where the case's frame, the corner 6e-8 inside
      // and within F48's band, took the corner (F52, rigid-motion, manifuzz
      // fuzz --strict, open as O18).
      const bool inside_is_corner = !(start_inside ? start_crossing : end_crossing);
      const Vec3 foot = outside - d_outside * plane.normal;
      if (outside_is_corner && d_outside <= near_plane && along_edge(foot, edge, near_plane)) {
        ok &= out.push(foot);
      } else if (d_inside < -(inside_is_corner ? near_plane : on_plane)) {
        // The signs differ strictly (one < 0, the other > 0), so the
        // denominator is never zero and t lies in [0, 1].
        const double t = d_start / (d_start - d_end);
        ok &= out.push(start + t * (end - start), true);
      }
    }
    if (end_inside) ok &= out.push(end, end_crossing);
    start = end;
    d_start = d_end;
    start_crossing = end_crossing;
    start_inside = end_inside;
  }
  return ok;
}

void remove_points_outside(ClipPolygon& polygon, const Plane& plane) {
  for (int k = polygon.size() - 1; k >= 0; --k)
    if (plane.signed_distance(polygon[k]) > 0) polygon.erase(k);
}

namespace {

// Twice the signed area of the triangle o, a, b in the projection's plane:
// positive where b lies to the left of o -> a.
double turn(const Vec3& o, const Vec3& a, const Vec3& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

}  // namespace

// Andrew's monotone chain on the points projected onto two axes across
// `normal`, held in `scratch` as (x, y, 0); sorted by x, then y, then
// number, so that equal projections keep one order in every call.
void keep_outline(ClipPolygon& points, const Vec3& normal, ClipPolygon& scratch) {
  const int n = points.size();
  if (n < 3) return;
  const Vec3 across = normal.unitOrthogonal(), up = normal.cross(across);
  scratch.clear();
  for (int k = 0; k < n; ++k) scratch.push(Vec3(across.dot(points[k]), up.dot(points[k]), 0), points.is_crossing(k));
  std::array<int, kMaxPolygonVertices> order;
  for (int k = 0; k < n; ++k) order[k] = k;
  std::sort(order.begin(), order.begin() + n, [&](int i, int j) {
    const Vec3 &p = scratch[i], &q = scratch[j];
    return p.x() != q.x() ? p.x() < q.x() : p.y() != q.y() ? p.y() < q.y() : i < j;
  });
  std::array<int, kMaxPolygonVertices + 1> hull;
  int h = 0;
  for (int pass = 0; pass < 2; ++pass) {  // the lower chain, then the upper
    const int floor = h;
    for (int s = 0; s < n; ++s) {
      const int k = order[pass == 0 ? s : n - 1 - s];
      while (h >= floor + 2 && turn(scratch[hull[h - 2]], scratch[hull[h - 1]], scratch[k]) <= 0) --h;
      hull[h++] = k;
    }
    --h;  // each chain's last point starts the other
  }
  scratch.take(points);
  points.clear();
  for (int k = 0; k < h; ++k) points.push(scratch[hull[k]], scratch.is_crossing(hull[k]));
}

void reduce_polygon(ClipPolygon& polygon, int capacity) {
  while (polygon.size() > capacity) {
    const int n = polygon.size();
    int weakest = 0;
    double least = std::numeric_limits<double>::infinity();
    for (int k = 0; k < n; ++k) {
      const Vec3& prev = polygon[previous_corner(k, n)];
      const Vec3& next = polygon[next_corner(k, n)];
      const double area = (polygon[k] - prev).cross(next - polygon[k]).norm();
      if (area < least) least = area, weakest = k;
    }
    polygon.erase(weakest);
  }
}

}  // namespace mfz
