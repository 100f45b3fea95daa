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
/// Built into arrays an object allocates once, on its first build (SAT keeps
/// two per thread), so a generator call still allocates nothing; a hull too
/// large for the arrays, or one whose edges do not pair up, reports
/// `complete() == false` and SAT then tries every pair as the tutorial does.
#include <memory>

#include "geometry/posed_hull.h"

namespace mfz {

/// Every polyhedron with V vertices has at most 3V - 6 edges: the arcs of
/// any hull that has a topology (hull_topology.h).
inline constexpr int kMaxArcs = 3 * kTopologyMaxVertices;

/// A column's length: kMaxArcs and one cache line more, so that the twelve
/// columns do not all start at one offset modulo 4 KB (kMaxArcs doubles are
/// six pages), where a small hull's arcs, at the head of each column, would
/// compete for one set of the cache.
inline constexpr int kArcColumnLength = kMaxArcs + 8;

/// An arc's vertices and faces: what a pair's own tests read besides the
/// arcs' ends and circles.
struct ArcIndices {
  int v0, v1, face, twin;
};

struct EdgeArc {
  int v0, v1;      ///< v0 < v1; the step v0 -> v1 lies in the loop of `face`
  int face, twin;  ///< the faces on either side
  Vec3 n_face, n_twin;  ///< their world normals: the arc's ends
  Vec3 across;     ///< n_twin x n_face: normal to the arc's great circle
};

/// Loops over arcs in vector lanes run whole fours of them.
inline constexpr int kArcLanes = 4;
/// `count` rounded up to whole fours: a loop in lanes runs to it.
inline constexpr int lanes_of(int count) { return (count + kArcLanes - 1) / kArcLanes * kArcLanes; }

/// The arcs' ends, circles and first vertices as columns (x, y, z apart),
/// for loops over every arc at once in vector lanes. Past the last arc, up
/// to the next whole four (lanes_of), every column holds zeros, so that
/// such a loop needs no scalar tail; what those lanes give is thrown away.
/// 296 KB: kept off the stack (SAT keeps its in a workspace per thread).
struct ArcColumns {
  double face_x[kArcColumnLength], face_y[kArcColumnLength], face_z[kArcColumnLength];        ///< n_face
  double twin_x[kArcColumnLength], twin_y[kArcColumnLength], twin_z[kArcColumnLength];        ///< n_twin
  double across_x[kArcColumnLength], across_y[kArcColumnLength], across_z[kArcColumnLength];  ///< across
  double v0_x[kArcColumnLength], v0_y[kArcColumnLength], v0_z[kArcColumnLength];              ///< world v0
};

/// Each arc's edge, v1 - v0 in world space, as columns (x, y, z).
struct EdgeVectors {
  double x[kMaxArcs], y[kMaxArcs], z[kMaxArcs];
};

class EdgeArcs {
 public:
  EdgeArcs() = default;
  /// The arcs in SAT's edge order: loop steps with v0 < v1, faces in order.
  explicit EdgeArcs(const PosedHull& hull) { build(hull); }
  /// The same, into this object: SAT keeps two per thread rather than 43 KB
  /// each on the stack of every call.
  void build(const PosedHull& hull);
  bool complete() const { return complete_; }
  int size() const { return count_; }
  /// Arc i, gathered from the columns and the vertex and face indices.
  EdgeArc operator[](int i) const {
    const ArcColumns& c = storage_->columns;
    const ArcIndices& at = storage_->indices[i];
    return {at.v0,
            at.v1,
            at.face,
            at.twin,
            Vec3(c.face_x[i], c.face_y[i], c.face_z[i]),
            Vec3(c.twin_x[i], c.twin_y[i], c.twin_z[i]),
            Vec3(c.across_x[i], c.across_y[i], c.across_z[i])};
  }
  /// Arc i's vertices and faces alone.
  const ArcIndices& indices(int i) const { return storage_->indices[i]; }
  /// may_span_minkowski_face of A's arc and arc j of these, read from the
  /// columns: a pair the lanes let through is tested without gathering the
  /// whole arc (64-gon cylinders, whose rows let through many, took 1.06x
  /// the time when each was gathered).
  bool may_cross(const EdgeArc& arc_a, int j) const;
  /// Whether arc j lies between coplanar faces (is_flat_arc), read from the
  /// columns.
  bool is_flat(int j) const;
  /// False when no arc can be flat: a hull of merged faces (Qhull's) has
  /// none, and its pairs are not asked.
  bool may_have_flat() const { return may_have_flat_; }
  /// The arcs as columns: the only copy of their ends, circles and first
  /// vertices. Each arc was kept as a struct as well, and the columns were
  /// filled from the structs: a 128-point pair's call wrote 138 KB of arcs,
  /// and building and filling took 16% of its time. Only while the hull
  /// built from is alive.
  const ArcColumns& columns() const { return storage_->columns; }

  /// Writes each arc's edge vector (edge_vectors), from the hull built
  /// from: only SAT's rows of many pairs read them (generator/pair_bounds.h),
  /// so a build leaves them unwritten.
  void write_edge_vectors(const PosedHull& hull);
  /// What write_edge_vectors wrote.
  const EdgeVectors& edge_vectors() const { return storage_->edges; }

  /// The arcs (of B) that may cross `arc_a` (an arc of A's):
  /// may_span_minkowski_face's three tests, for every arc at once, in
  /// vector lanes. A margin over the test's slack covers the lanes' other
  /// rounding, so that every pair the test keeps is among these; the test
  /// itself then decides. Writes their indices to `out`; returns how many.
  int crossing(const EdgeArc& arc_a, int* out) const;

 private:
  bool pair_twins(const PosedHull& hull);
  void write_columns(const PosedHull& hull);
  void write_columns_one_by_one(const PosedHull& hull, ArcColumns& columns);

  struct Storage {
    ArcIndices indices[kMaxArcs];
    ArcColumns columns;
    EdgeVectors edges;
  };
  std::unique_ptr<Storage> storage_;  ///< allocated by the first build
  int count_ = 0;
  bool complete_ = false;
  bool may_have_flat_ = false;
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
/// The same with B's arc given by its ends and circle.
inline bool may_span_minkowski_face(const EdgeArc& edge_a, const Vec3& b_face, const Vec3& b_twin,
                                    const Vec3& b_across) {
  constexpr double slack = tol::kGaussArcSlack;
  // Most pairs fail the first test: the other two dot products only for
  // those that pass.
  const double cba = -b_face.dot(edge_a.across);
  const double dba = -b_twin.dot(edge_a.across);
  if (!(cba * dba < slack)) return false;
  const double adc = edge_a.n_face.dot(b_across);
  const double bdc = edge_a.n_twin.dot(b_across);
  return adc * bdc < slack && cba * bdc > -slack;
}

inline bool may_span_minkowski_face(const EdgeArc& edge_a, const EdgeArc& edge_b) {
  return may_span_minkowski_face(edge_a, edge_b.n_face, edge_b.n_twin, edge_b.across);
}

/// F4: an arc between coplanar faces (coplanar_normals of its ends), such as
/// a triangulated face's diagonal, spans no axis. Its circle's normal is the
/// cross product of the same ends: only where twice the coplanar sine bounds
/// it is the test itself asked, so that an arc across a fold costs three
/// products.
inline constexpr double kFlatArcRoom = 4 * tol::kCoplanarSine * tol::kCoplanarSine;
inline bool is_flat_arc(const Vec3& n_face, const Vec3& n_twin, const Vec3& across) {
  return across.squaredNorm() <= kFlatArcRoom && coplanar_normals(n_face, n_twin);
}

inline bool is_flat_arc(const EdgeArc& arc) { return is_flat_arc(arc.n_face, arc.n_twin, arc.across); }

inline bool EdgeArcs::is_flat(int j) const {
  const ArcColumns& c = storage_->columns;
  return is_flat_arc(Vec3(c.face_x[j], c.face_y[j], c.face_z[j]), Vec3(c.twin_x[j], c.twin_y[j], c.twin_z[j]),
                     Vec3(c.across_x[j], c.across_y[j], c.across_z[j]));
}

inline bool EdgeArcs::may_cross(const EdgeArc& arc_a, int j) const {
  const ArcColumns& c = storage_->columns;
  return may_span_minkowski_face(arc_a, Vec3(c.face_x[j], c.face_y[j], c.face_z[j]),
                                 Vec3(c.twin_x[j], c.twin_y[j], c.twin_z[j]),
                                 Vec3(c.across_x[j], c.across_y[j], c.across_z[j]));
}

}  // namespace mfz
