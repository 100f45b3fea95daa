// F3 (FINDINGS.md): on an edge-edge axis neither significant face is
// perpendicular to n, so clipping one against the other puts point_on_b off
// B's surface. The contact is instead the closest pair of points of the two
// edges that support the hulls along n and -n.
#include <cmath>
#include <limits>

#include "clipping_generator.h"
#include "tolerances.h"

namespace mfz {
namespace {

struct Segment {
  Vec3 from, to;
};

// The supporting edge along `direction`: the edge whose nearer end reaches
// furthest along it. It is defined by the axis alone: SAT may have met the
// axis through any edge perpendicular to it, and several can be (F6: a
// frustum's polygon edges), so the edge that made the axis is not the one to
// use; nor is a test for perpendicular edges, which a nearly parallel twin 1e-9
// rad off fails depending on which of the two made the axis (F12).
bool supporting_edge(const PosedHull& hull, const Vec3& direction, Segment& edge) {
  double best = -std::numeric_limits<double>::infinity();
  for (int f = 0; f < hull.face_count(); ++f) {
    const int n = hull.face_size(f);
    for (int k = 0; k < n; ++k) {
      const Vec3 from = hull.world_face_point(f, k), to = hull.world_face_point(f, (k + 1) % n);
      const Vec3 d = to - from;
      const double length = d.norm();
      if (!(length > 0)) continue;
      const double reach = std::min(direction.dot(from), direction.dot(to));
      if (reach > best) best = reach, edge = {from, to};
    }
  }
  return best > -std::numeric_limits<double>::infinity();
}

// Closest points of two segments: Ericson, Real-Time Collision Detection, 5.1.9.
void closest_points(const Segment& s1, const Segment& s2, Vec3& c1, Vec3& c2) {
  const Vec3 d1 = s1.to - s1.from, d2 = s2.to - s2.from, r = s1.from - s2.from;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  const double c = d1.dot(r), b = d1.dot(d2), denom = a * e - b * b;
  // Parallel segments (denom 0) have a line of closest pairs: take s = 0.
  double s = denom > 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
  double t = e > 0 ? (b * s + f) / e : 0.0;
  if (t < 0) t = 0, s = a > 0 ? std::clamp(-c / a, 0.0, 1.0) : 0.0;
  else if (t > 1) t = 1, s = a > 0 ? std::clamp((b - c) / a, 0.0, 1.0) : 0.0;
  c1 = s1.from + s * d1;
  c2 = s2.from + t * d2;
}

}  // namespace

bool no_edge_contact(const PosedHull&, const PosedHull&, const SatResult&, mfz_manifold&) { return false; }

bool closest_points_of_edges(const PosedHull& a, const PosedHull& b, const SatResult& sat, mfz_manifold& out) {
  Segment on_a, on_b;
  if (!supporting_edge(a, sat.normal, on_a) || !supporting_edge(b, -sat.normal, on_b))
    return false;  // no edge supports the axis: fall back to clipping faces
  Vec3 point_a, point_b;
  closest_points(on_a, on_b, point_a, point_b);
  // Only edges whose shadows along n cross make an edge contact; otherwise
  // the axis came from a near-tie with a face axis: clip faces instead.
  // The tolerance adds the rounding of world coordinates far from the origin.
  const double reach = (on_a.to - on_a.from).norm() + (on_b.to - on_b.from).norm();
  const double extent = on_a.from.cwiseAbs().maxCoeff() + on_b.from.cwiseAbs().maxCoeff();
  const double slack = tol::kEdgesCross * reach + tol::kWorldUlps * std::numeric_limits<double>::epsilon() * extent;
  if (!((point_b - (point_a - sat.depth * sat.normal)).norm() <= slack)) return false;
  // point_on_b = point_on_a + p n exactly; the edge's own closest point
  // point_b agrees with it to rounding, because n is the edges' common normal.
  const double p = -sat.depth;
  mfz_contact& c = out.contacts[out.contact_count++];
  c.point_on_a = to_abi(point_a);
  c.point_on_b = to_abi(Vec3(point_a + p * sat.normal));
  c.penetration = p;
  return true;
}

}  // namespace mfz
