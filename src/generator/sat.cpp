#include "generator/sat.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "generator/coplanar_patch.h"
#include "generator/edge_arcs.h"
#include "geometry/tolerances.h"

namespace mfz {

double overlap_along(const PosedHull& a, const PosedHull& b, const Vec3& axis, bool& b_along_axis) {
  const Interval ia = a.project(axis), ib = b.project(axis);
  const double b_above = ia.max - ib.min;  // overlap if B is pushed out along +axis
  const double b_below = ib.max - ia.min;  // overlap if B is pushed out along -axis
  b_along_axis = b_above <= b_below;
  return b_along_axis ? b_above : b_below;
}

namespace {

// The area of the face's coplanar patch: a triangulated face weighs as much
// as the whole face it came from.
double face_area_of(const PosedHull& a, const PosedHull& b, const SatResult& axis) {
  return axis.kind == AxisKind::face_a ? patch_area(a, axis.feature_a) : patch_area(b, axis.feature_b);
}

// Faces of the two hulls along one direction with overlaps within `slack`.
bool parallel_face_tie(const PosedHull&, const PosedHull&, const SatResult& x, const SatResult& y, double slack) {
  const bool faces = x.kind != AxisKind::edge_edge && y.kind != AxisKind::edge_edge && x.kind != y.kind;
  return faces && std::abs(x.depth - y.depth) <= slack && coplanar_normals(x.normal, y.normal);
}

// Tries one candidate axis (unit length). Returns false when it separates.
// An edge axis must beat a face axis by tol::kEdgeAxisBias of the
// extent (F3), and a face normal counts for depth only in the direction of a
// face of the Minkowski difference: A's outward, B's inward (F7). Reversed,
// a face normal still proves separation, but the hull's support along it is
// an edge or a vertex, not that face, and the penetration axis lies among
// the other candidates.
bool consider(const PosedHull& a, const PosedHull& b, const Vec3& axis, AxisKind kind, int fa, int fb,
              SatResult& best) {
  const Interval ia = a.project(axis), ib = b.project(axis);
  const double b_above = ia.max - ib.min, b_below = ib.max - ia.min;
  if (b_above < 0 || b_below < 0) {
    const bool along = b_above <= b_below;
    best = {true, along ? axis : Vec3(-axis), along ? b_above : b_below, kind, fa, fb};
    return false;
  }
  bool b_along_axis = b_above <= b_below;
  if (kind == AxisKind::face_a) b_along_axis = true;
  if (kind == AxisKind::face_b) b_along_axis = false;
  const double overlap = b_along_axis ? b_above : b_below;
  // The margin adds the world frame's rounding (F9): far from the origin an
  // edge pair along a face normal can come out smaller by rounding alone.
  const double world = std::max({std::abs(ia.min), std::abs(ia.max), std::abs(ib.min), std::abs(ib.max)});
  const double slack = tol::kEdgeAxisBias * std::max(ia.max - ia.min, ib.max - ib.min) +
                       tol::world_rounding(world);
  const bool edge_after_face = kind == AxisKind::edge_edge && best.kind != AxisKind::edge_edge;
  const Vec3 normal = b_along_axis ? axis : Vec3(-axis);
  const SatResult candidate{false, normal, overlap, kind, fa, fb};
  if (overlap < best.depth - (edge_after_face ? slack : 0.0)) {
    // F14: a face that ties with a parallel face of the other hull only
    // rounds below it; the larger face stays the reference, whatever the
    // order of the hulls or the motion.
    if (!(parallel_face_tie(a, b, candidate, best, slack) && face_area_of(a, b, candidate) <= face_area_of(a, b, best)))
      best = candidate;
  } else if (parallel_face_tie(a, b, candidate, best, slack) &&
             face_area_of(a, b, candidate) > face_area_of(a, b, best)) {
    best = candidate;
  }
  return true;
}


// One edge pair's axis. Returns false when it separates. `flat` says whether
// either edge lies between coplanar faces; it is asked only of an axis about
// to win.
template <class FlatTest>
bool consider_edge_pair(const PosedHull& a, const PosedHull& b, int ea, int a0, int a1, int eb, int b0, int b1,
                        SatResult& best, FlatTest&& flat) {
  const Vec3 edge_a = a.world_vertex(a1) - a.world_vertex(a0);
  const Vec3 edge_b = b.world_vertex(b1) - b.world_vertex(b0);
  const Vec3 axis = edge_a.cross(edge_b);
  const double length = axis.norm();
  // Parallel edges span no new axis (a face normal covers it); dividing by
  // a vanishing length would only amplify rounding.
  if (length <= tol::kParallelEdges * edge_a.norm() * edge_b.norm()) return true;
  SatResult candidate = best;
  const bool separated = !consider(a, b, axis / length, AxisKind::edge_edge, ea, eb, candidate);
  if (!separated && candidate.depth == best.depth) return true;
  if (flat()) return true;
  best = candidate;
  return !separated;
}

// Every edge pair: the reference the pruning is checked against, and the
// fallback for a hull whose edge arcs are incomplete.
void all_edge_pairs(const PosedHull& a, const PosedHull& b, SatResult& best) {
  bool separated = false;
  a.for_each_edge([&](int ea, int a0, int a1, int face_a) {
    b.for_each_edge([&](int eb, int b0, int b1, int face_b) {
      separated = !consider_edge_pair(a, b, ea, a0, a1, eb, b0, b1, best, [&] {
        return a.is_flat_edge(a0, a1, face_a) || b.is_flat_edge(b0, b1, face_b);
      });
      return !separated;
    });
    return !separated;
  });
}

// Only the pairs whose Gauss arcs may cross: the others span no face of the
// Minkowski difference, so their overlap exceeds the depth (edge_arcs.h).
void minkowski_edge_pairs(const PosedHull& a, const PosedHull& b, const EdgeArcs& arcs_a, const EdgeArcs& arcs_b,
                          SatResult& best) {
  for (int i = 0; i < arcs_a.size(); ++i) {
    const EdgeArc& x = arcs_a[i];
    for (int j = 0; j < arcs_b.size(); ++j) {
      const EdgeArc& y = arcs_b[j];
      if (!may_span_minkowski_face(x, y)) continue;
      const bool apart = !consider_edge_pair(a, b, i, x.v0, x.v1, j, y.v0, y.v1, best, [&] {
        return coplanar_normals(x.n_face, x.n_twin) || coplanar_normals(y.n_face, y.n_twin);
      });
      if (apart) return;
    }
  }
}

// The harness's fixes F3 (face axes win near-ties), F4 (flat edges span no
// axis), F7 (face normals count one way only) and F14 (parallel faces tie to
// the larger), with edge pairs pruned on the Gauss map unless `prune` is off.
SatResult sat_with(const PosedHull& a, const PosedHull& b, bool prune) {
  SatResult best;
  best.depth = std::numeric_limits<double>::infinity();
  for (int f = 0; f < a.face_count(); ++f)
    if (!consider(a, b, a.world_face_normal(f), AxisKind::face_a, f, -1, best)) return best;
  for (int f = 0; f < b.face_count(); ++f)
    if (!consider(a, b, b.world_face_normal(f), AxisKind::face_b, -1, f, best)) return best;
  if (prune) {
    const EdgeArcs arcs_a(a), arcs_b(b);
    if (arcs_a.complete() && arcs_b.complete()) {
      minkowski_edge_pairs(a, b, arcs_a, arcs_b, best);
      return best;
    }
  }
  all_edge_pairs(a, b, best);
  return best;
}

}  // namespace

SatResult run_sat(const PosedHull& a, const PosedHull& b) { return sat_with(a, b, true); }
SatResult run_sat_every_pair(const PosedHull& a, const PosedHull& b) { return sat_with(a, b, false); }

}  // namespace mfz
