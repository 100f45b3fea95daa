#pragma once
/// \file
/// A brute-force separating-axis test over world-space vertex lists: every
/// face normal of both hulls and every edge pair, every vertex projected, no
/// pruning and no early exit. Slow and plain on purpose: the reference that
/// optimised SATs are checked against, and the source of the ranked axes
/// `explain` shows and of tie detection.
#include <vector>

#include "scene.h"
#include "sat.h"

namespace mfz {

/// Overlap of the projections along `n` with B pushed out along +n:
/// max over A of n.x minus min over B of n.x (negative: separated along n).
double directed_overlap(const std::vector<Vec3>& world_a, const std::vector<Vec3>& world_b, const Vec3& n);

struct RankedAxis {
  Vec3 normal;  ///< unit, from A to B: a face of A outward, of B inward, an edge pair the smaller way
  double overlap = 0;
  AxisKind kind = AxisKind::face_a;
  int feature_a = -1, feature_b = -1;
};

/// Every candidate axis with its overlap, smallest overlap first.
std::vector<RankedAxis> rank_sat_axes(const Scene& scene);

/// True when another candidate has an overlap within `tie` of the minimum and
/// could lead to another manifold: another kind of axis, another face, or
/// another direction (CONTRACT.md, "Ties").
bool has_axis_tie(const std::vector<RankedAxis>& ranked, double tie);

}  // namespace mfz
