#pragma once
/// \file
/// A posed hull's edges on its Gauss map: each edge is the arc between the
/// world normals of its two faces. An edge of A and an edge of B span a face
/// of the Minkowski difference A - B only where A's arc crosses B's arc
/// negated, and only such a face can hold the penetration axis: every other
/// edge pair's overlap is larger (Gregorius, "The Separating Axis Test
/// between Convex Polyhedra", GDC 2013). Pruning the other pairs turns SAT's
/// E_A x E_B projections into a handful.
///
/// Built on the stack, so a generator call still allocates nothing; a hull
/// too large for the arrays, or one whose edges do not pair up, reports
/// `complete() == false` and SAT then tries every pair as the tutorial does.
#include "geometry/posed_hull.h"

namespace mfz {

/// Every polyhedron with V vertices has at most 3V - 6 edges.
inline constexpr int kMaxArcs = 3 * kCachedVertices;

struct EdgeArc {
  int v0, v1;      ///< v0 < v1; the step v0 -> v1 lies in the loop of `face`
  int face, twin;  ///< the faces on either side
  Vec3 n_face, n_twin;  ///< their world normals: the arc's ends
  Vec3 across;     ///< n_twin x n_face: normal to the arc's great circle
};

/// The arcs' ends, circles and first vertices as columns (x, y, z apart),
/// for loops over every arc at once in vector lanes.
struct ArcColumns {
  double face_x[kMaxArcs], face_y[kMaxArcs], face_z[kMaxArcs];  ///< n_face
  double twin_x[kMaxArcs], twin_y[kMaxArcs], twin_z[kMaxArcs];  ///< n_twin
  double across_x[kMaxArcs], across_y[kMaxArcs], across_z[kMaxArcs];  ///< across
  double v0_x[kMaxArcs], v0_y[kMaxArcs], v0_z[kMaxArcs];        ///< world v0
};

class EdgeArcs {
 public:
  EdgeArcs() = default;
  /// The arcs in SAT's edge order: loop steps with v0 < v1, faces in order.
  explicit EdgeArcs(const PosedHull& hull) { build(hull); }
  /// The same, into this object: SAT keeps two per thread rather than 34 KB
  /// each on the stack of every call.
  void build(const PosedHull& hull);
  bool complete() const { return complete_; }
  int size() const { return count_; }
  const EdgeArc& operator[](int i) const { return arcs_[i]; }
  /// The arcs as columns, filled on first use after each build: SAT reads
  /// A's only where it bounds whole rows of large hulls, and a small pair's
  /// call filled them for nothing (8-point hulls 0.9% of a call). Only
  /// while the hull built from is alive, as the arcs' indices are.
  const ArcColumns& columns() const {
    if (!has_columns_) fill_columns();
    return columns_;
  }

  /// The arcs (of B) that may cross `arc_a` (an arc of A's):
  /// may_span_minkowski_face's three tests, for every arc at once, in
  /// vector lanes. A margin over the test's slack covers the lanes' other
  /// rounding, so that every pair the test keeps is among these; the test
  /// itself then decides. Writes their indices to `out`; returns how many.
  int crossing(const EdgeArc& arc_a, int* out) const;

 private:
  bool pair_twins(const PosedHull& hull);
  void fill_columns() const;

  EdgeArc arcs_[kMaxArcs];
  mutable ArcColumns columns_;
  const PosedHull* hull_ = nullptr;  ///< the hull built from, for its vertices
  int count_ = 0;
  bool complete_ = false;
  mutable bool has_columns_ = false;
};

/// Of the arcs in `all` (the first `count`), those whose `left_out` is
/// false, in order, as columns in `kept`, and each one's index in `index`.
/// Returns how many.
int keep_arcs(const ArcColumns& all, int count, const bool* left_out, ArcColumns& kept, int* index);

/// EdgeArcs::crossing over arcs kept by keep_arcs: the indices written to
/// `out` are those of `index`, in order.
int crossing_among(const ArcColumns& kept, int count, const int* index, const EdgeArc& arc_a, int* out);

/// False only when the arcs certainly do not cross, so that the pair spans
/// no face of A - B. Rounding of the sign tests is given the benefit of the
/// doubt: a flat or nearly flat edge (a fold of 1e-9 rad) is kept, and SAT's
/// own rules decide about it as before.
/// The arcs of A's edge (a -> b) and of B's edge negated (c -> d) cross when
/// c and d lie either side of the plane of a, b, a and b either side of the
/// plane of c, d, and the two crossings are one point, not antipodes.
/// Inline: SAT asks it of every pair of edges.
inline bool may_span_minkowski_face(const EdgeArc& edge_a, const EdgeArc& edge_b) {
  constexpr double slack = tol::kGaussArcSlack;
  // Most pairs fail the first test: the other two dot products only for
  // those that pass.
  const double cba = -edge_b.n_face.dot(edge_a.across);
  const double dba = -edge_b.n_twin.dot(edge_a.across);
  if (!(cba * dba < slack)) return false;
  const double adc = edge_a.n_face.dot(edge_b.across);
  const double bdc = edge_a.n_twin.dot(edge_b.across);
  return adc * bdc < slack && cba * bdc > -slack;
}

}  // namespace mfz
