#pragma once
/// \file
/// A brute-force separating-axis test over world-space vertex lists: every
/// face normal of both hulls and every edge pair, every vertex projected, no
/// pruning and no early exit. Plain on purpose: the reference that optimised
/// SATs are checked against, the source of the ranked axes `explain` shows
/// and of tie detection, and the exact depth.
///
/// Why exact: the overlap along a unit n is the support function of the
/// Minkowski difference A - B, h(n) = max over A of n.a - min over B of n.b.
/// Every facet normal of A - B is among the candidates (a face of A outward,
/// a face of B inward, or the cross product of an edge of each), and for the
/// origin inside A - B, h(n) >= (distance to the boundary) for every n. So
/// the least overlap is the distance from the origin to the boundary of
/// A - B, which is the contract's exact depth, computed without the
/// generator's SAT. Qhull's hull of the vertex differences
/// (minkowski_difference.h) gives the same number; a property checks that.
#include <limits>
#include <vector>

#include "case/scene.h"
#include "geometry/axis_kind.h"

namespace mfz {

/// Overlap of the projections along `n` with B pushed out along +n:
/// max over A of n.x minus min over B of n.x (negative: separated along n).
double directed_overlap(const std::vector<Vec3>& world_a, const std::vector<Vec3>& world_b, const Vec3& n);

struct RankedAxis {
  Vec3 normal;  ///< unit, from A to B: a face of A outward, of B inward, an edge pair the smaller way
  double overlap = 0;
  /// An edge pair's overlap along -normal (a facet of A - B may face either
  /// way); +inf for a face axis, whose other way is no facet.
  double reverse_overlap = 0;
  AxisKind kind = AxisKind::face_a;
  int feature_a = -1, feature_b = -1;
};

/// Axes within this (x L) of the least overlap are ranked: a thousand times
/// the tie tolerance, so that tie detection reads sorted axes only.
inline constexpr double kRankedWindow = 1e-6;

/// Every candidate axis with its overlap: least overlap first, sorted as far
/// as kRankedWindow past it (at least three axes); the rest in no order.
/// Where `least_reverse` is given, it receives least_reverse_overlap of the
/// answer, found as the axes are written.
std::vector<RankedAxis> rank_sat_axes(const Scene& scene, double* least_reverse = nullptr);

/// The least reverse overlap among `ranked` (+inf where none is less): an
/// edge axis's other way is a facet of A - B too, and those overlaps are
/// not ranked. Whether any axis's reverse overlap is within a tie of the
/// best overlap is whether this one is (subtracting the best rounds the
/// same way for every axis). Read off the whole list, as it is unordered:
/// the two scans of it in the tie checks were 6% of a 32-point property
/// case, whose 8,000 axes no longer sit in the cache by then.
double least_reverse_overlap(const std::vector<RankedAxis>& ranked);

/// How deep B would still be after moving it by t: min over the candidates of
/// overlap - n.t, both ways for edge pairs. Positive exactly when B moved by t
/// still overlaps A (t inside A - B); outside, a negative lower bound.
/// With `stop_at`, the first value at or below it is returned as soon as it
/// is met, for a caller that asks only whether the least is above: moved
/// past the depth along the answer's normal, the best axis (first) is
/// there already, and the other 8,000 of two 32-point hulls are not read.
double depth_after_moving_b(const std::vector<RankedAxis>& axes, const Vec3& t,
                            double stop_at = -std::numeric_limits<double>::infinity());

/// True when depth_after_moving_b(ranked, t) is certainly positive, told by
/// the least overlap alone: each candidate's value is an overlap less n.t,
/// or a reverse overlap (never less than the overlap) plus n.t, for a unit
/// n, so while |t| and room for the dot product's rounding stay below the
/// least overlap (ranked[0]'s), every value is positive. False says
/// nothing. Moving B short of the depth is the usual question, and the pass
/// over 8,000 axes that no longer sit in the cache was 4% of a 32-point
/// property case.
bool surely_overlapping_after_moving_b(const std::vector<RankedAxis>& ranked, const Vec3& t);

/// True when another candidate has an overlap within `tie` of the minimum and
/// could lead to another manifold: another kind of axis, another face, or
/// another direction, the reverse of an edge pair's axis included
/// (docs/contract.md, "Ties").
/// `least_reverse` is least_reverse_overlap(ranked).
bool has_axis_tie(const std::vector<RankedAxis>& ranked, double tie, double least_reverse);

/// True when a face axis is among the candidates within `tie` of the least
/// overlap along the best direction.
bool has_minimal_face_axis(const std::vector<RankedAxis>& ranked, double tie);

}  // namespace mfz
