// SAT's pass over every edge pair (least_edge_axis, F39's answer, and the
// reference run_sat_every_pair): measured a stretch of pairs at a time in
// vector lanes, it answers as measuring one pair at a time does, to the bit.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <random>
#include <sstream>
#include <string>

#include "families.h"
#include "generator/sat.h"
#include "geometry/hull.h"
#include "geometry/tolerances.h"
#include "test_support.h"

namespace mfz {
namespace {

// The least edge axis as the pass measured it before its stretches: each
// pair's cross product made unit and both hulls projected onto it alone;
// parallel edges give no axis, a flat edge (between coplanar faces) never
// wins, and the first pair that separates ends the pass.
SatResult least_edge_axis_pair_by_pair(const PosedHull& a, const PosedHull& b) {
  SatResult best;
  best.depth = std::numeric_limits<double>::infinity();
  best.kind = AxisKind::edge_edge;
  bool separated = false;
  a.for_each_edge([&](int ea, int a0, int a1, int face_a) {
    b.for_each_edge([&](int eb, int b0, int b1, int face_b) {
      const Vec3 edge_a = a.world_vertex(a1) - a.world_vertex(a0), edge_b = b.world_vertex(b1) - b.world_vertex(b0);
      const Vec3 axis = edge_a.cross(edge_b);
      const double length = axis.norm();
      if (length <= tol::kParallelEdges * edge_a.norm() * edge_b.norm()) return true;
      const Vec3 unit = axis / length;
      const Interval ia = a.project(unit), ib = b.project(unit);
      const double b_above = ia.max - ib.min, b_below = ib.max - ia.min;
      const bool along = b_above <= b_below;
      const double overlap = along ? b_above : b_below;
      const bool apart = b_above < 0 || b_below < 0;
      if (!apart && !(overlap < best.depth)) return true;
      if (a.is_flat_edge(a0, a1, face_a) || b.is_flat_edge(b0, b1, face_b)) return true;
      best = {apart, along ? unit : Vec3(-unit), overlap, AxisKind::edge_edge, ea, eb};
      separated = apart;
      return !separated;
    });
    return !separated;
  });
  return best;
}

// The same answer to the bit: an infinite depth (no pair spans an axis)
// compares too, and so does the zero's sign.
bool same_bits(const SatResult& x, const SatResult& y) {
  const bool same_depth = (x.depth == y.depth && std::signbit(x.depth) == std::signbit(y.depth)) ||
                          (std::isinf(x.depth) && std::isinf(y.depth));
  return x.separated == y.separated && x.kind == y.kind && x.feature_a == y.feature_a &&
         x.feature_b == y.feature_b && same_depth && x.normal == y.normal;
}

std::string described(const SatResult& r) {
  std::ostringstream text;
  text << std::setprecision(17) << (r.separated ? "separated" : "overlapping") << " edges " << r.feature_a << " x "
       << r.feature_b << " depth " << r.depth << " normal (" << r.normal.transpose() << ")";
  return text.str();
}

// Clouds of 4 to 128 points (the largest whose world vertices a posed hull
// caches, past which the pass goes a pair at a time as before), from
// touching to nearly concentric, and their fan-triangulated copies, whose
// diagonals are flat edges; B's edges past a stretch's 64 fill several.
TEST(EveryEdgePair, LeastEdgeAxisMeasuredInStretchesIsThePairByPairAnswerToTheBit) {
  std::mt19937 random(20261207);
  int separated = 0, flat_hulls = 0;
  for (unsigned seed = 1; seed <= 48; ++seed) {
    const int sizes[] = {4, 8, 24, 60, 128};
    const test::OverlappingClouds clouds(test::sphere_points(sizes[seed % 5], seed), sizes[(seed / 5) % 5], 900 + seed,
                                         random);
    const PosedHull a(clouds.view_a, clouds.pose_a), b(clouds.view_b, clouds.pose_b);
    SCOPED_TRACE("seed " + std::to_string(seed));
    const SatResult pairs = least_edge_axis_pair_by_pair(a, b);
    separated += pairs.separated;
    const SatResult stretches = least_edge_axis(a, b);
    EXPECT_TRUE(same_bits(stretches, pairs)) << described(stretches) << "\n against " << described(pairs);
    if (seed % 4 != 0) continue;
    ++flat_hulls;
    const Hull fans = fan_triangulated(clouds.hull_a);
    const mfz_hull fan_view = fans.view();
    const PosedHull fan_a(fan_view, clouds.pose_a);
    const SatResult fan_stretches = least_edge_axis(fan_a, b), fan_pairs = least_edge_axis_pair_by_pair(fan_a, b);
    EXPECT_TRUE(same_bits(fan_stretches, fan_pairs)) << described(fan_stretches) << "\n against " << described(fan_pairs);
  }
  EXPECT_EQ(flat_hulls, 12);
  // Clouds placed from touching spheres inward: some are apart (the pass
  // ends at a separating pair), most overlap (every pair is read).
  EXPECT_GT(separated, 0);
  EXPECT_LT(separated, 24);
}

// Over every family of the property suite (boxes, folds, slabs, 64-gons,
// far frames, touching and apart): the same bits, separating pairs too.
RC_GTEST_PROP(EveryEdgePair, LeastEdgeAxisIsThePairByPairAnswerInEveryFamily, ()) {
  const props::GeneratedCase c = *props::any_case();
  const test::PosedCase posed(c.file);
  RC_PRE(posed.built);
  const PosedHull a = posed.a(), b = posed.b();
  RC_TAG(c.placement);
  const SatResult stretches = least_edge_axis(a, b), pairs = least_edge_axis_pair_by_pair(a, b);
  RC_LOG() << described(stretches) << "\n against " << described(pairs) << "\n";
  RC_ASSERT(same_bits(stretches, pairs));
}

}  // namespace
}  // namespace mfz
