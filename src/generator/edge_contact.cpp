// F3 (FINDINGS.md): on an edge-edge axis neither significant face is
// perpendicular to n, so clipping one against the other puts point_on_b off
// B's surface. The contact is instead the closest pair of points of the two
// edges that support the hulls along n and -n.
#include <algorithm>
#include <cmath>
#include <limits>

#include "generator/clipping_generator.h"
#include "generator/contact_output.h"
#include "generator/supporting_edges.h"
#include "geometry/closest_point.h"
#include "geometry/tolerances.h"

namespace mfz {
namespace {

struct Segment {
  Vec3 from, to;
};

// The supporting edges (generator/supporting_edges.h) as segments in world space.
template <class Visit>
void each_supporting_segment(const PosedHull& hull, const SupportingEdges& edges, Visit&& visit) {
  edges.each([&](int, int v0, int v1) { visit(Segment{hull.world_vertex(v0), hull.world_vertex(v1)}); });
}

bool holds_contact(const mfz_manifold& out, int first, const Vec3& point_a) {
  for (int k = first; k < out.contact_count; ++k)
    if (to_vec(out.contacts[k].point_on_a) == point_a) return true;
  return false;
}

}  // namespace


bool closest_points_of_edges(const PosedHull& a, const PosedHull& b, const SatResult& sat, mfz_manifold& out) {
  // The sets SAT named the axis by, where they are this axis's.
  AxisSupport own;
  const bool named = sat.support && sat.support->holds(a, b, sat.normal);
  if (!named) own.take(a, b, sat.normal);
  const SupportingEdges &supporting_a = named ? *sat.support->a : *own.a, &supporting_b = named ? *sat.support->b : *own.b;
  // Every candidate pair whose closest points lie along n at the depth, to
  // rounding: the pairs that cross (F16). Where two parallel edges of one
  // hull are equally deep to rounding (an edge across a thin face turned
  // 1e-6 rad from n, 1e6 L out), each crossing is a contact: picking one
  // would leave a contact a face's width away to rounding (F20).
  const int first = out.contact_count;
  each_supporting_segment(a, supporting_a, [&](const Segment& edge_a) {
    each_supporting_segment(b, supporting_b, [&](const Segment& edge_b) {
      Vec3 point_a, point_b;
      closest_between_segments(edge_a.from, edge_a.to, edge_b.from, edge_b.to, point_a, point_b);
      const double miss = (point_b - (point_a - sat.depth * sat.normal)).norm();
      // The miss is how far the contact's point on B, put at point_a + p n
      // below, stands off B's edge: on-surface holds it to 1e-9 L, so it is
      // bounded by the longer edge, which no hull's diameter falls short of,
      // not by the two edges' lengths added up. Added up, two edges of two
      // tetrahedra 1e4 long took a pair that missed by 2e-5 (1.8e-9 L), and
      // its point on B stood that far off B (rigid-motion, manifold_fuzzer,
      // F62). The tolerance adds the rounding of world coordinates far from
      // the origin.
      const double longer = std::max((edge_a.to - edge_a.from).norm(), (edge_b.to - edge_b.from).norm());
      const double extent = edge_a.from.cwiseAbs().maxCoeff() + edge_b.from.cwiseAbs().maxCoeff();
      const double slack = tol::kEdgesCross * longer + tol::world_rounding(extent);
      // Only edges whose shadows along n cross make an edge contact; otherwise
      // the axis came from a near-tie with a face axis: clip faces instead.
      if (!(miss <= slack)) return;
      // point_on_b = point_on_a + p n exactly; the edge's own closest point
      // agrees with it to rounding, because n is the edges' common normal.
      const double p = -(point_a - point_b).dot(sat.normal);
      if (!(p < 0) || out.contact_count == MFZ_MAX_CONTACTS || holds_contact(out, first, point_a)) return;
      add_contact(out, point_a, point_a + p * sat.normal, p);
    });
  });
  return out.contact_count > first;
}

}  // namespace mfz
