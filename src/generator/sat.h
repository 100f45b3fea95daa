#pragma once
/// \file
/// The separating-axis test the tutorial's generator starts from: every face
/// normal of A, every face normal of B, and the cross product of every edge of
/// A with every edge of B; the axis of least overlap gives the collision
/// normal and the penetration.
#include "generator/supporting_edges.h"
#include "geometry/axis_kind.h"
#include "geometry/posed_hull.h"

namespace mfz {

/// The outcome of SAT. When `separated`, `normal` is a separating axis and
/// `depth` the (negative) overlap along it; otherwise `normal` is the unit axis
/// of least overlap oriented from A towards B and `depth` >= 0 the overlap.
struct SatResult {
  bool separated = false;
  Vec3 normal = Vec3::UnitZ();
  double depth = 0;
  AxisKind kind = AxisKind::face_a;
  int feature_a = -1;  ///< face of A, or edge of A (index into its unique edges in loop order)
  int feature_b = -1;  ///< face of B, or edge of B
  /// On an edge axis, the supporting edges SAT named it by (F51), in the
  /// thread's SAT workspace: valid until the thread's next SAT call, and
  /// only while they hold the hulls and the normal (AxisSupport::holds).
  const AxisSupport* support = nullptr;
};

/// The features whose axis answered a pair's last call: SAT measures it
/// first, and its overlap caps the edge pairs' bounds (sat.cpp).
struct AxisHint {
  AxisKind kind = AxisKind::face_a;
  int feature_a = -1, feature_b = -1;  ///< as in SatResult; -1 for none
};

/// Overlap of A and B along a unit world axis, and which way B lies.
/// Returns the smaller of the two overlaps; `b_along_axis` tells whether it is
/// the one with B on the +axis side (so the normal from A to B is +axis).
double overlap_along(const PosedHull& a, const PosedHull& b, const Vec3& axis, bool& b_along_axis);

/// The built-in generator's SAT: candidates in the order A's faces, B's
/// faces, edge pairs; stops at the first separating axis; allocates nothing.
/// Unlike the tutorial's (generator/baseline), an edge axis must
/// beat the face axes by tol::kEdgeAxisBias (F3), edges between coplanar
/// faces give no axis (F4), a face normal counts one way only (F7), only
/// edge pairs whose Gauss arcs may cross are tried (edge_arcs.h, among the
/// arcs of B that arc_bounds.h leaves in on large hulls, and on small ones
/// not a pair whose axis lies along a face normal at an arc's end), and an
/// axis is measured in full only when a cheap lower bound on its overlap
/// leaves it a chance (sat.cpp). An edge axis is answered by the first
/// pair of supporting edges that spans it, where one does (F51).
///
/// The axis that answered the same pair's last call on this thread is tried
/// first (the pair is known by the addresses of its hulls' vertices): where
/// it separates the hulls by more than rounding, SAT ends there, and
/// otherwise its overlap caps the edge pairs' bounds (not the faces':
/// F43). The answer
/// is the one without the hint, to the bit, except the separating axis
/// reported for hulls apart, which the contract leaves free.
SatResult run_sat(const PosedHull& a, const PosedHull& b);
/// run_sat with `hint` for the pair's last axis, whatever the pair's
/// history; no hint (a feature -1) gives the answer from nothing.
SatResult run_sat_with_hint(const PosedHull& a, const PosedHull& b, const AxisHint& hint);
/// How many edge pairs the thread's last SAT call that reached its edge
/// pairs measured in full, both hulls projected onto their axis: what the
/// Gauss test, the arc ends and the bounds leave. Two parallelepipeds, whose
/// nine axes are measured apart, and a call that ends on a face leave the
/// count of the call before. For tests.
int edge_pairs_measured_in_full();
/// How many edge pairs of large hulls (past the small hulls' batch) the
/// same call formed an axis for one at a time, after the Gauss test and
/// the row's tests in vector lanes; the same calls leave the count before.
/// For tests.
int edge_pairs_formed_alone();
/// How many faces of either hull the same call bounded past the other
/// hull's ball (hulls of more than 16 vertices): each then climbs to, or
/// projects, the other hull's support. For tests.
int faces_past_the_balls();
/// Every axis measured in full and every edge pair tried: what the pruning
/// and the bounds must agree with.
SatResult run_sat_every_pair(const PosedHull& a, const PosedHull& b);
/// The edge pair of least overlap, every pair tried, without F3's bias
/// towards faces: the axis a face axis beat by less than the bias (F39).
/// `depth` is infinite when no pair spans an axis.
SatResult least_edge_axis(const PosedHull& a, const PosedHull& b);

}  // namespace mfz
