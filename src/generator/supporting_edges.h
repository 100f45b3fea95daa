#pragma once
/// \file
/// The edges of a hull that support it along a direction: the edge whose
/// nearer end reaches furthest along it, and every edge within rounding of
/// that reach. An edge-edge axis makes its contact from them (F3), and SAT
/// names its answer by them (F51).
#include <limits>
#include <optional>

#include "geometry/posed_hull.h"

namespace mfz {

// The axis alone defines them: SAT may have met the axis through any edge
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
  SupportingEdges(const PosedHull& hull, const Vec3& direction);

  /// The first supporting edge in the hull's order (-1 for none), found
  /// without visiting the edges after it.
  int first() const;

  /// Calls `visit(edge, v0, v1)` for each supporting edge, in the hull's
  /// order: `edge` numbers it among the hull's edges as SatResult does.
  template <class Visit>
  void each(Visit&& visit) const {
    each_edge([&](int edge, int v0, int v1, double reach, const auto& is_flat) {
      if (reach >= threshold_ && !is_flat()) visit(edge, v0, v1);
      return true;
    });
  }

 private:
  // Each edge once (from its lower-numbered end), with its number, the
  // reach of its nearer end along the direction and a test, asked only of
  // an edge about to count, of whether it lies between two coplanar faces;
  // `visit` returns false to stop there.
  // A hull with a topology reads its edges, with the faces either side,
  // from it: the same edges in the same order, and the same test on the
  // same two normals, as the loops' steps give (a 128-point hull has 378
  // edges and 756 steps, each step's face across looked up again).
  template <class Visit>
  void each_edge(Visit&& visit) const {
    if (const HullTopology* topology = hull_.topology()) {
      for (int e = 0; e < topology->edge_count(); ++e) {
        const TopologyEdge& edge = topology->edge(e);
        if (!visit(e, edge.v0, edge.v1, std::min(height(edge.v0), height(edge.v1)), [&] {
              return coplanar_normals(hull_.world_face_normal(edge.twin), hull_.world_face_normal(edge.face));
            }))
          return;
      }
      return;
    }
    int e = 0;
    for (int f = 0; f < hull_.face_count(); ++f) {
      const int n = hull_.face_size(f);
      for (int k = 0; k < n; ++k) {
        const int v0 = hull_.face_vertex(f, k), v1 = hull_.face_vertex(f, (k + 1) % n);
        if (v0 < v1 &&
            !visit(e++, v0, v1, std::min(height(v0), height(v1)), [&] { return hull_.is_flat_step(f, k); }))
          return;
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

/// The supporting edges of both hulls along one axis: A's along `normal`,
/// B's along its reverse. SAT names an edge axis by them and leaves them
/// for the edge contact, which reads the same sets: taking them twice was
/// 4-5% of a random hull's call.
struct AxisSupport {
  std::optional<SupportingEdges> a, b;
  Vec3 normal = Vec3::Zero();
  const PosedHull *hull_a = nullptr, *hull_b = nullptr;

  void take(const PosedHull& posed_a, const PosedHull& posed_b, const Vec3& along) {
    a.emplace(posed_a, along), b.emplace(posed_b, -along);
    normal = along, hull_a = &posed_a, hull_b = &posed_b;
  }
  /// Whether these are the supporting edges of these hulls along `along`,
  /// to the bit.
  bool holds(const PosedHull& posed_a, const PosedHull& posed_b, const Vec3& along) const {
    return hull_a == &posed_a && hull_b == &posed_b && normal == along;
  }
};

}  // namespace mfz
