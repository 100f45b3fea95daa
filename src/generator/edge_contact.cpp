// F3 (FINDINGS.md): on an edge-edge axis neither significant face is
// perpendicular to n, so clipping one against the other puts point_on_b off
// B's surface. The contact is instead the closest pair of points of the two
// edges that support the hulls along n and -n.
#include <cmath>
#include <limits>

#include "generator/clipping_generator.h"
#include "generator/contact_output.h"
#include "geometry/closest_point.h"
#include "geometry/tolerances.h"

namespace mfz {
namespace {

struct Segment {
  Vec3 from, to;
};

// The supporting edges along `direction`: the edge whose nearer end reaches
// furthest along it, and every edge within rounding of that reach. The axis
// alone defines them: SAT may have met the axis through any edge
// perpendicular to it, and several can be (F6: a frustum's polygon edges);
// nor is a test for perpendicular edges right, which a nearly parallel twin
// 1e-9 rad off fails depending on which of the two made the axis (F12).
// The rounding is that of the coordinates the heights are computed from, not
// of the heights: a needle across n has heights of 1e-3 and vertices 116
// away, and the edge SAT's axis came from, 2.7e-15 below an edge 3.6e-12
// long at the tip, was left out (a slack of 4.9e-16); no pair crossed, and
// the driver clipped a sliver face 15 degrees off n (F31, open as O3 since
// the first campaigns). Nor is the hull's extent along n the measure of a
// tie: a needle 9900 long lies across n, 6.9e-4 deep along it, and its long
// edge, 2.7e-4 rad from the other hull's, made the axis; turned and moved
// 7.6e3 out, the axis's rounding over that angle left the edge's far end
// 2.5e-10 below its near end, past 1e-9 of 6.9e-4 and the rounding of
// 9900. Only the short edge beside it supported A, no pair crossed, and
// the driver clipped faces 0.118 off B (F47, rigid-motion, open as O14).
// 1e-9 of the hull's span, a size no pose changes, holds it.
// They are visited, not listed: any cap on their number lets the hull's
// numbering pick which are left out. A needle 1.3e-8 thin and 16000 long has
// 45 edges within the world's rounding of its reach, 13 of them crossing B's
// edge; the first 32 held none of the 13 once its vertices were numbered
// backwards, and the driver clipped a face 6.7 off A (F34, open as O7).
class SupportingEdges {
 public:
  SupportingEdges(const PosedHull& hull, const Vec3& direction) : hull_(hull), direction_(direction) {
    double best = -std::numeric_limits<double>::infinity(), lowest = std::numeric_limits<double>::infinity();
    double extent = 0;
    for (int i = 0; i < hull.vertex_count(); ++i) {
      const Vec3 p = hull.world_vertex(i);
      const double height = direction.dot(p);
      if (i < kKeptHeights) heights_[i] = height;
      lowest = std::min(lowest, height);
      extent = std::max(extent, p.cwiseAbs().maxCoeff());
    }
    // F22: a diagonal between two triangles of one face would add a contact
    // that the face untriangulated does not have.
    each_edge([&](int, int, double reach, const auto& is_flat) {
      if (reach > best && !is_flat()) best = reach;
    });
    threshold_ = best - (tol::kTie * std::max(best - lowest, hull.span()) +
                         tol::world_rounding(std::max(std::abs(best), extent)));
  }

  /// Calls `visit(segment)` for each supporting edge, in the hull's order.
  template <class Visit>
  void each(Visit&& visit) const {
    each_edge([&](int v0, int v1, double reach, const auto& is_flat) {
      if (reach >= threshold_ && !is_flat()) visit(Segment{hull_.world_vertex(v0), hull_.world_vertex(v1)});
    });
  }

 private:
  // Each edge once (from its lower-numbered end), with the reach of its
  // nearer end along the direction and a test, asked only of an edge about
  // to count, of whether it lies between two coplanar faces. A hull with a
  // topology reads its edges, with the faces either side, from it: the same
  // edges in the same order, and the same test on the same two normals, as
  // the loops' steps give (a 128-point hull has 378 edges and 756 steps,
  // each step's face across looked up again).
  template <class Visit>
  void each_edge(Visit&& visit) const {
    if (const HullTopology* topology = hull_.topology()) {
      for (int e = 0; e < topology->edge_count(); ++e) {
        const TopologyEdge& edge = topology->edge(e);
        visit(edge.v0, edge.v1, std::min(height(edge.v0), height(edge.v1)), [&] {
          return coplanar_normals(hull_.world_face_normal(edge.twin), hull_.world_face_normal(edge.face));
        });
      }
      return;
    }
    for (int f = 0; f < hull_.face_count(); ++f) {
      const int n = hull_.face_size(f);
      for (int k = 0; k < n; ++k) {
        const int v0 = hull_.face_vertex(f, k), v1 = hull_.face_vertex(f, (k + 1) % n);
        if (v0 < v1) visit(v0, v1, std::min(height(v0), height(v1)), [&] { return hull_.is_flat_step(f, k); });
      }
    }
  }

  // Each vertex's height along the direction, taken once: both passes
  // took both ends' heights per edge, six per vertex of three edges
  // (SupportingEdges and its visits 9% of a 128-point call, 7% after).
  // Past the buffer, taken again, to the same bits.
  static constexpr int kKeptHeights = kCachedVertices;
  double height(int v) const { return v < kKeptHeights ? heights_[v] : direction_.dot(hull_.world_vertex(v)); }

  const PosedHull& hull_;
  Vec3 direction_;
  double threshold_ = 0;
  double heights_[kKeptHeights];
};

bool holds_contact(const mfz_manifold& out, int first, const Vec3& point_a) {
  for (int k = first; k < out.contact_count; ++k)
    if (to_vec(out.contacts[k].point_on_a) == point_a) return true;
  return false;
}

}  // namespace


bool closest_points_of_edges(const PosedHull& a, const PosedHull& b, const SatResult& sat, mfz_manifold& out) {
  const SupportingEdges supporting_a(a, sat.normal), supporting_b(b, -sat.normal);
  // Every candidate pair whose closest points lie along n at the depth, to
  // rounding: the pairs that cross (F16). Where two parallel edges of one
  // hull are equally deep to rounding (an edge across a thin face turned
  // 1e-6 rad from n, 1e6 L out), each crossing is a contact: picking one
  // would leave a contact a face's width away to rounding (F20).
  const int first = out.contact_count;
  supporting_a.each([&](const Segment& edge_a) {
    supporting_b.each([&](const Segment& edge_b) {
      Vec3 point_a, point_b;
      closest_between_segments(edge_a.from, edge_a.to, edge_b.from, edge_b.to, point_a, point_b);
      const double miss = (point_b - (point_a - sat.depth * sat.normal)).norm();
      // The tolerance adds the rounding of world coordinates far from the origin.
      const double reach = (edge_a.to - edge_a.from).norm() + (edge_b.to - edge_b.from).norm();
      const double extent = edge_a.from.cwiseAbs().maxCoeff() + edge_b.from.cwiseAbs().maxCoeff();
      const double slack = tol::kEdgesCross * reach + tol::world_rounding(extent);
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
