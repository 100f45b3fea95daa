// SAT's hint: the axis that answered a pair's last call, measured first.
// It may end SAT where it separates the hulls, and bounds every other axis
// where it does not; either way the answer is the one found without it, so
// a generator's answer never depends on what it was asked before (a
// finding must replay in a fresh process).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <memory>
#include <random>
#include <vector>

#include "families.h"
#include "generator/sat.h"
#include "geometry/hull.h"
#include "test_support.h"

namespace mfz {
namespace {

// The hints a pair can meet: each face of either hull, edge pairs spread
// over the whole grid (the winning one among them), and the pair's own
// answer. At most about `budget` in all, spread evenly.
std::vector<AxisHint> hints_for(const PosedHull& a, const PosedHull& b, const SatResult& answer, int budget) {
  std::vector<AxisHint> hints = {{answer.kind, answer.feature_a, answer.feature_b}};
  const int faces_a = a.face_count(), faces_b = b.face_count();
  for (int f = 0; f < faces_a; f += std::max(1, faces_a / (budget / 3))) hints.push_back({AxisKind::face_a, f, -1});
  for (int f = 0; f < faces_b; f += std::max(1, faces_b / (budget / 3))) hints.push_back({AxisKind::face_b, -1, f});
  const HullTopology *ta = a.topology(), *tb = b.topology();
  if (!ta || !tb) return hints;
  const long pairs = long{ta->edge_count()} * tb->edge_count();
  const long stride = std::max(1L, pairs / (budget / 3));
  for (long k = 0; k < pairs; k += stride)
    hints.push_back({AxisKind::edge_edge, static_cast<int>(k / tb->edge_count()), static_cast<int>(k % tb->edge_count())});
  return hints;
}

// The answer with the hint is the answer without it: to the bit where the
// hulls overlap, and apart where they are apart (with any separating axis).
// Returns how many hints were tried.
int expect_every_hint_gives(const PosedHull& a, const PosedHull& b, int budget) {
  const SatResult cold = run_sat_with_hint(a, b, AxisHint{});
  const std::vector<AxisHint> hints = hints_for(a, b, cold, budget);
  for (const AxisHint& hint : hints) {
    const SatResult warm = run_sat_with_hint(a, b, hint);
    RC_LOG() << "hint " << axis_kind_name(hint.kind) << " " << hint.feature_a << "/" << hint.feature_b << ": "
             << axis_kind_name(warm.kind) << " " << warm.feature_a << "/" << warm.feature_b << " depth " << warm.depth
             << "; without: " << axis_kind_name(cold.kind) << " " << cold.feature_a << "/" << cold.feature_b
             << " depth " << cold.depth << "\n";
    RC_ASSERT(warm.separated == cold.separated);
    if (cold.separated) continue;
    RC_ASSERT(warm.kind == cold.kind);
    RC_ASSERT(warm.feature_a == cold.feature_a);
    RC_ASSERT(warm.feature_b == cold.feature_b);
    RC_ASSERT(warm.depth == cold.depth);
    RC_ASSERT(warm.normal == cold.normal);
  }
  return static_cast<int>(hints.size());
}

// Every family of the property suite, touching and far frames included.
RC_GTEST_PROP(SatHint, AnyHintGivesTheAnswerFoundWithoutOne, ()) {
  const props::GeneratedCase c = *props::any_case();
  const test::PosedCase posed(c.file);
  RC_PRE(posed.built);
  RC_TAG(c.placement);
  expect_every_hint_gives(posed.a(), posed.b(), 24);
}

// Clouds of 24 to 128 points, where faces are bounded by balls and climbs
// and whole rows of edge pairs by their arcs (the hint bounds those too),
// overlapping from touching to nearly concentric; and each pair's hints
// taken from the pair a little further on, as a moving pair meets them.
TEST(SatHint, LargeHullsGiveTheAnswerFoundWithoutAHint) {
  std::mt19937 random(20261127);
  std::normal_distribution<double> gauss;
  const auto direction = [&] { return Vec3(gauss(random), gauss(random), gauss(random)).normalized(); };
  int tried = 0, edge_answers = 0, moved_hints = 0;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    const int sizes[] = {24, 48, 96, 128};
    const test::OverlappingClouds clouds(test::sphere_points(sizes[seed % 4], seed), sizes[(seed / 4) % 4],
                                         1000 + seed, random);
    const PosedHull posed_a(clouds.view_a, clouds.pose_a), posed_b(clouds.view_b, clouds.pose_b);
    tried += expect_every_hint_gives(posed_a, posed_b, 60);
    const SatResult here = run_sat_with_hint(posed_a, posed_b, AxisHint{});
    edge_answers += !here.separated && here.kind == AxisKind::edge_edge;
    // The pair a step further on, turned a little, with this pose's axis.
    const Pose pb_next{(clouds.apart * 0.97) * clouds.towards,
                       test::about(direction(), 0.02) * clouds.pose_b.orientation};
    const PosedHull next_b(clouds.view_b, pb_next);
    const SatResult next = run_sat_with_hint(posed_a, next_b, AxisHint{});
    const SatResult hinted = run_sat_with_hint(posed_a, next_b, {here.kind, here.feature_a, here.feature_b});
    EXPECT_EQ(hinted.separated, next.separated) << "seed " << seed;
    if (next.separated) continue;
    ++moved_hints;
    EXPECT_EQ(hinted.kind, next.kind) << "seed " << seed;
    EXPECT_EQ(hinted.feature_a, next.feature_a) << "seed " << seed;
    EXPECT_EQ(hinted.feature_b, next.feature_b) << "seed " << seed;
    EXPECT_EQ(hinted.depth, next.depth) << "seed " << seed;
  }
  EXPECT_GT(tried, 2000);
  EXPECT_GT(edge_answers, 5) << "edge pairs should answer some of the pairs";
  EXPECT_GT(moved_hints, 30);
}

struct BoxPair {
  Hull hull_a = *build_hull(test::box_points(1, 1, 1)).hull;
  Hull hull_b = *build_hull(test::box_points(1, 1, 1)).hull;
  mfz_hull a = hull_a.view(), b = hull_b.view();
  Pose pose_a{Vec3::Zero(), Quat::Identity()};
};

// A hint that separates the hulls answers at once, with its own axis, though
// SAT from nothing finds an earlier one in its order.
TEST(SatHint, ASeparatingHintAnswersWithItsOwnAxis) {
  const BoxPair boxes;
  const Pose pose_b{Vec3(3, 3, 0), Quat::Identity()};
  const PosedHull a(boxes.a, boxes.pose_a), b(boxes.b, pose_b);
  const SatResult cold = run_sat_with_hint(a, b, AxisHint{});
  ASSERT_TRUE(cold.separated);
  ASSERT_EQ(cold.kind, AxisKind::face_a) << "A's faces come first";
  int later = -1;  // a face of B along the other axis that separates them
  for (int f = 0; f < b.face_count() && later < 0; ++f) {
    const Vec3 n = b.world_face_normal(f);
    if (std::abs(n.dot(cold.normal)) < 0.5 && std::abs(n.z()) < 0.5) later = f;
  }
  ASSERT_GE(later, 0);
  const SatResult warm = run_sat_with_hint(a, b, {AxisKind::face_b, -1, later});
  EXPECT_TRUE(warm.separated);
  EXPECT_EQ(warm.kind, AxisKind::face_b);
  EXPECT_EQ(warm.feature_b, later);
  EXPECT_LT(warm.depth, 0);
}

// run_sat remembers each pair's axis: the same hulls called again start from
// it, so the pair apart along x, then moved to be apart along x and y, is
// still answered along x, where SAT from nothing would take y's face first
// (or the other way about).
TEST(SatHint, TheSamePairCalledAgainStartsFromItsLastAxis) {
  const BoxPair boxes;
  const PosedHull a(boxes.a, boxes.pose_a);
  const Pose diagonal{Vec3(3, 3, 0), Quat::Identity()};
  const SatResult cold = run_sat_with_hint(a, PosedHull(boxes.b, diagonal), AxisHint{});
  ASSERT_TRUE(cold.separated);
  // First apart along the axis SAT from nothing does not take.
  const Vec3 first_offset = std::abs(cold.normal.x()) > 0.5 ? Vec3(0, 3, 0) : Vec3(3, 0, 0);
  const Pose first_pose{first_offset, Quat::Identity()};
  const SatResult first = run_sat(a, PosedHull(boxes.b, first_pose));
  ASSERT_TRUE(first.separated);
  const SatResult again = run_sat(a, PosedHull(boxes.b, diagonal));
  EXPECT_TRUE(again.separated);
  EXPECT_EQ(again.kind, first.kind);
  EXPECT_EQ(again.feature_a, first.feature_a);
  EXPECT_EQ(again.feature_b, first.feature_b);
  EXPECT_NE(again.feature_a, cold.feature_a) << "SAT from nothing takes another face";
  // Another pair of hulls (the same box built again, elsewhere in memory)
  // has no hint.
  const Hull other = *build_hull(test::box_points(1, 1, 1)).hull;
  const mfz_hull other_view = other.view();
  const SatResult stranger = run_sat(a, PosedHull(other_view, diagonal));
  EXPECT_EQ(stranger.feature_a, cold.feature_a);
}

// A thousand pairs, each met once apart along one axis, then again where
// SAT from nothing takes another: nearly every one starts from its own
// last axis. The benchmark cycles through 1,024 pairs a family, as an
// engine meets its pairs frame after frame; with one pair to a slot, the
// pairs whose slot another took started from nothing (204 to 245 of 1,024
// in five runs).
// Four to a set, 5 to 57 did in 25 runs (the addresses, and so the sets,
// move from run to run): nine in ten is the bar.
TEST(SatHint, AThousandPairsEachKeepTheirLastAxis) {
  constexpr int kPairs = 1024;
  std::vector<Hull> hulls;
  for (int i = 0; i < 2 * kPairs; ++i) hulls.push_back(*build_hull(test::box_points(1, 1, 1)).hull);
  std::vector<mfz_hull> views;
  for (const Hull& h : hulls) views.push_back(h.view());
  const Pose origin{Vec3::Zero(), Quat::Identity()}, diagonal{Vec3(3, 3, 0), Quat::Identity()};
  const SatResult cold = run_sat_with_hint(PosedHull(views[0], origin), PosedHull(views[1], diagonal), AxisHint{});
  ASSERT_TRUE(cold.separated);
  const Pose first_pose{std::abs(cold.normal.x()) > 0.5 ? Vec3(0, 3, 0) : Vec3(3, 0, 0), Quat::Identity()};
  std::vector<SatResult> first;
  for (int i = 0; i < kPairs; ++i)
    first.push_back(run_sat(PosedHull(views[2 * i], origin), PosedHull(views[2 * i + 1], first_pose)));
  int kept = 0;
  for (int i = 0; i < kPairs; ++i) {
    const SatResult again = run_sat(PosedHull(views[2 * i], origin), PosedHull(views[2 * i + 1], diagonal));
    ASSERT_TRUE(again.separated);
    kept += again.kind == first[i].kind && again.feature_a == first[i].feature_a && again.feature_b == first[i].feature_b;
  }
  EXPECT_GE(kept, kPairs * 9 / 10) << kPairs - kept << " of " << kPairs << " pairs started from nothing";
}

// F43: a tetrahedron 1.1e-16 behind a face of A, apart along that face's
// normal reversed, which SAT without a hint measures first. With that face
// as the hint, the faces were bounded by it from the first on, in their
// own directions only: the face was left out, a later one overlapped by
// 1.1e-16, and the second call said colliding. Every hint must say apart.
TEST(SatHint, AFaceThatSeparatesReversedAtTouchingIsMeasuredWhateverTheHint) {
  const CaseParse parsed = read_case_file(
      test::corpus_path("regressions/f43-the-pair-s-last-axis-left-out-a-face-that-separated-reversed-at-touching.case"));
  ASSERT_TRUE(parsed.value.has_value()) << parsed.error;
  const test::PosedCase posed(*parsed.value);
  ASSERT_TRUE(posed.built);
  const PosedHull a = posed.a(), b = posed.b();
  const SatResult cold = run_sat_with_hint(a, b, AxisHint{});
  ASSERT_TRUE(cold.separated);
  ASSERT_EQ(cold.kind, AxisKind::face_a);
  for (int f = 0; f < a.face_count(); ++f)
    EXPECT_TRUE(run_sat_with_hint(a, b, {AxisKind::face_a, f, -1}).separated) << "hint: face " << f << " of A";
  for (int f = 0; f < b.face_count(); ++f)
    EXPECT_TRUE(run_sat_with_hint(a, b, {AxisKind::face_b, -1, f}).separated) << "hint: face " << f << " of B";
}

// A regression case's hulls, posed in the generator's frame (centred on A's
// position), where the campaigns met them; null, with a failure, when the
// case does not read or build.
std::unique_ptr<test::PosedCase> regression_centred_on_a(const std::string& name) {
  const CaseParse parsed = read_case_file(test::corpus_path("regressions/" + name));
  EXPECT_TRUE(parsed.value.has_value()) << parsed.error;
  if (!parsed.value) return nullptr;
  auto posed = std::make_unique<test::PosedCase>(*parsed.value);
  EXPECT_TRUE(posed->built) << name;
  if (!posed->built) return nullptr;
  posed->centre_on_a();
  return posed;
}

// Gives each edge pair along `cold`'s axis (to 1e-6 rad) as the hint, and
// expects the call to answer as `cold`, to the bit; returns how many pairs
// lie along it.
int hints_along_the_axis_answering_as(const PosedHull& a, const PosedHull& b, const SatResult& cold) {
  const HullTopology &ta = *a.topology(), &tb = *b.topology();
  int along = 0;
  for (int ea = 0; ea < ta.edge_count(); ++ea)
    for (int eb = 0; eb < tb.edge_count(); ++eb) {
      const Vec3 edge_a = a.world_vertex(ta.edge(ea).v1) - a.world_vertex(ta.edge(ea).v0);
      const Vec3 edge_b = b.world_vertex(tb.edge(eb).v1) - b.world_vertex(tb.edge(eb).v0);
      const Vec3 axis = edge_a.cross(edge_b);
      if (!(axis.norm() > 1e-6 * edge_a.norm() * edge_b.norm()) || axis.normalized().cross(cold.normal).norm() > 1e-6)
        continue;
      ++along;
      const SatResult warm = run_sat_with_hint(a, b, {AxisKind::edge_edge, ea, eb});
      EXPECT_EQ(warm.separated, cold.separated) << "hint: A's edge " << ea << " with B's " << eb;
      EXPECT_EQ(warm.feature_a, cold.feature_a) << "hint: A's edge " << ea << " with B's " << eb;
      EXPECT_EQ(warm.feature_b, cold.feature_b) << "hint: A's edge " << ea << " with B's " << eb;
      EXPECT_EQ(warm.depth, cold.depth) << "hint: A's edge " << ea << " with B's " << eb;
      EXPECT_EQ(warm.normal, cold.normal) << "hint: A's edge " << ea << " with B's " << eb;
    }
  return along;
}

// F51: a 29-point hull with five edges along one direction against a
// 7-point hull with two: ten edge pairs give one axis, each to its own
// rounding, and one pair supports the hulls. The first call kept a pair
// that does not (A's edge 60 with B's 11); with it as the hint, the bounds
// left A's row 60 out and kept 18 with 11, 1.2e-16 deeper. Whichever pair
// along the axis is the hint, the answer is the one without a hint, to the
// bit, named by the supporting pair. In the generator's frame, centred on
// A's position, where the fuzzer met it.
TEST(SatHint, EdgePairsAlongOneAxisAnswerWithTheSameBitsWhicheverIsTheHint) {
  const auto posed = regression_centred_on_a(
      "f51-edge-pairs-along-one-axis-named-by-the-bounds-so-a-hint-picked-another-1e-16-deeper.case");
  ASSERT_TRUE(posed);
  const PosedHull a = posed->a(), b = posed->b();
  const SatResult cold = run_sat_with_hint(a, b, AxisHint{});
  ASSERT_FALSE(cold.separated);
  ASSERT_EQ(cold.kind, AxisKind::edge_edge);
  EXPECT_EQ(hints_along_the_axis_answering_as(a, b, cold), 10) << "five edges of A and two of B along the axis";
}

// F54: a needle touching a cone, 2.0008883439004421e-11 deep, where two
// edge axes 7 degrees apart (A's edges 13 and 25, each with B's edge 2)
// have the same overlap to the bit. Without a hint SAT answers with the
// first; with that answer as the hint, the hint's ceiling let the bounds
// meet the second first, and the second call answered with it. With its
// own answer as the hint, a call answers as the call without one.
TEST(SatHint, TwoEdgeAxesTiedAtTouchingAnswerAsTheColdCallWithItsAnswerAsTheHint) {
  const auto posed = regression_centred_on_a(
      "f54-two-edge-axes-7-degrees-apart-tie-at-touching-and-the-hint-s-ceiling-picked-the-other.case");
  ASSERT_TRUE(posed);
  const PosedHull a = posed->a(), b = posed->b();
  const SatResult cold = run_sat_with_hint(a, b, AxisHint{});
  ASSERT_FALSE(cold.separated);
  ASSERT_EQ(cold.kind, AxisKind::edge_edge);
  const SatResult warm = run_sat_with_hint(posed->a(), posed->b(), {cold.kind, cold.feature_a, cold.feature_b});
  EXPECT_EQ(warm.feature_a, cold.feature_a);
  EXPECT_EQ(warm.feature_b, cold.feature_b);
  EXPECT_EQ(warm.depth, cold.depth);
  EXPECT_EQ(warm.normal, cold.normal);
}

// F56: two needles, 1e-3 and 1e-6 wide, touching corner to corner 1e3 from
// the origin, 5.5e-15 deep. SAT takes the edge axis from the
// parallelepipeds' zones' first edges and names it by the supporting
// edges; the hint recomputed the axis from those, and B's edge, 1e-3 long,
// turned it by 4e-11, enough for an overlap of -3.0e-14 past the hint's
// band of rounding. Whichever pair along the axis is the hint, the call
// answers as the call without one, to the bit.
TEST(SatHint, ParallelEdgesOfTouchingNeedlesAsTheHintAnswerAsTheColdCall) {
  const auto posed = regression_centred_on_a(
      "f56-two-needles-touching-corner-to-corner-1e3-out-a-hint-named-by-another-edge-proved-them-apart.case");
  ASSERT_TRUE(posed);
  const PosedHull a = posed->a(), b = posed->b();
  const SatResult cold = run_sat_with_hint(a, b, AxisHint{});
  ASSERT_FALSE(cold.separated);
  ASSERT_EQ(cold.kind, AxisKind::edge_edge);
  EXPECT_EQ(hints_along_the_axis_answering_as(a, b, cold), 16) << "four edges of each needle along the axis";
}

}  // namespace
}  // namespace mfz
