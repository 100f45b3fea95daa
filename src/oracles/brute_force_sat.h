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
  Vec3 normal;  ///< unit, oriented from A to B (the smaller of the two overlaps)
  double overlap = 0;
  AxisKind kind = AxisKind::face_a;
  int feature_a = -1, feature_b = -1;
};

/// Every candidate axis with its overlap, smallest overlap first.
std::vector<RankedAxis> rank_sat_axes(const Scene& scene);

/// True when an axis whose direction differs from the best one's by more than
/// a few degrees has an overlap within `tie` of the minimum.
bool has_axis_tie(const std::vector<RankedAxis>& ranked, double tie);

}  // namespace mfz
