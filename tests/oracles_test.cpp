#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <tuple>

#include "case/case_file.h"
#include "oracles/brute_force_sat.h"
#include "oracles/contact_region.h"
#include "oracles/exact_depth.h"
#include "geometry/tolerances.h"
#include "oracles/libccd_oracle.h"
#include "geometry/closest_point.h"
#include "geometry/hull_distance.h"
#include "oracles/hull_gap.h"
#include "oracles/minkowski_difference.h"
#include "oracles/ties.h"
#include "families.h"
#include "test_support.h"

namespace mfz {
namespace {

using test::box_points;

Scene scene_of(const CaseFile& c) {
  SceneBuild built = make_scene(c);
  if (!built.scene) {
    ADD_FAILURE() << built.error;
    std::abort();
  }
  return std::move(*built.scene);
}

// Two needles crossing through each other, a minimised case from check:
// an edge axis ties with its own reverse (h4).
Scene crossing_needles() {
  const CaseParse parsed =
      read_case_file(test::corpus_path("regressions/h4-crossing-needles-tie-with-the-reverse-axis.case"));
  if (!parsed.value) {
    ADD_FAILURE() << parsed.error;
    std::abort();
  }
  return scene_of(*parsed.value);
}

// `count` pairs of clouds of 4 to 32 points on unit spheres, B at `b_at`
// and turned a little more with each seed.
std::vector<Scene> sphere_cloud_pairs(unsigned count, const Vec3& b_at) {
  std::vector<Scene> scenes;
  for (unsigned seed = 1; seed <= count; ++seed)
    scenes.push_back(scene_of(test::make_case(test::sphere_points(4 + static_cast<int>(seed * 7 % 29), seed), {},
                                              test::sphere_points(4 + static_cast<int>(seed * 13 % 29), 100 + seed),
                                              {b_at, test::about(Vec3(1, 2, 3), 0.1 * seed)})));
  return scenes;
}

Scene box_on_slab(const Vec3& offset = Vec3::Zero()) {
  return scene_of(test::make_case(box_points(2, 2, 0.5), {offset, Quat::Identity()}, box_points(0.5, 0.5, 0.5),
                                  {offset + Vec3(0, 0, 0.9), Quat::Identity()}));
}

TEST(MinkowskiOracle, DepthIsTheDistanceFromTheOriginToTheBoundary) {
  const Scene s = box_on_slab();
  std::string error;
  const auto md = MinkowskiDifference::build(s.world_a, s.world_b, error);
  ASSERT_TRUE(md) << error;
  const ExactDepth exact = md->at_origin();
  EXPECT_TRUE(exact.colliding);
  EXPECT_NEAR(exact.signed_depth, 0.1, 1e-14);
  EXPECT_VEC_NEAR(exact.normal, Vec3(0, 0, 1), 1e-14);
}

TEST(MinkowskiOracle, GapIsTheDistanceBetweenTheHullsCornerToCorner) {
  const Scene s = scene_of(test::make_case(box_points(0.5, 0.5, 0.5), {}, box_points(0.5, 0.5, 0.5),
                                           {Vec3(1.3, 1.4, 0), Quat::Identity()}));
  std::string error;
  const auto md = MinkowskiDifference::build(s.world_a, s.world_b, error);
  // The planes alone give only a lower bound: the nearest plane is 0.4 away.
  EXPECT_NEAR(md->at_origin().signed_depth, -0.4, 1e-14);
  const ExactDepth exact = exact_depth(s, rank_sat_axes(s));
  EXPECT_FALSE(exact.colliding);
  EXPECT_NEAR(exact.signed_depth, -std::hypot(0.3, 0.4), 1e-14);
  EXPECT_VEC_NEAR(exact.normal, Vec3(0.6, 0.8, 0), 1e-14);
}

TEST(ExactDepth, InsideIsTheLeastOverlapAndMovingBByItLeavesThemTouching) {
  const Scene s = box_on_slab();
  const auto axes = rank_sat_axes(s);
  const ExactDepth exact = exact_depth(s, axes);
  EXPECT_TRUE(exact.colliding);
  EXPECT_NEAR(exact.signed_depth, 0.1, 1e-15);
  EXPECT_VEC_NEAR(exact.normal, Vec3(0, 0, 1), 1e-15);
  EXPECT_GT(depth_after_moving_b(axes, Vec3(0, 0, 0.0999)), 0);
  EXPECT_NEAR(depth_after_moving_b(axes, Vec3(0, 0, 0.1)), 0, 1e-15);
  EXPECT_LT(depth_after_moving_b(axes, Vec3(0, 0, 0.1001)), 0);
  // Sideways B stays in contact until it slides off the slab's edge.
  EXPECT_GT(depth_after_moving_b(axes, Vec3(2.4, 0, 0)), 0);
  EXPECT_LT(depth_after_moving_b(axes, Vec3(2.6, 0, 0)), 0);
}

// A floor asks only whether the least is above it: the pass ends at the
// first axis at or below it, which moved past the depth along the answer's
// normal is the best axis, first (stop 64). Above the floor everywhere,
// the least is read in full.
TEST(ExactDepth, AFloorEndsThePassAtTheFirstAxisAtOrBelowIt) {
  const Scene s = box_on_slab();
  const auto axes = rank_sat_axes(s);
  // 0.05 past the depth, and off the slab's side: the best axis leaves
  // -0.05, the side's about -0.5.
  const Vec3 past = Vec3(3, 0, 0.15);
  const double least = depth_after_moving_b(axes, past);
  const double first = std::min(axes[0].overlap - axes[0].normal.dot(past),
                                axes[0].reverse_overlap + axes[0].normal.dot(past));
  ASSERT_LE(first, 0);
  ASSERT_LT(least, first);
  EXPECT_EQ(depth_after_moving_b(axes, past, 0.0), first);
  const Vec3 short_of = Vec3(0, 0, 0.05);
  EXPECT_EQ(depth_after_moving_b(axes, short_of, 0.0), depth_after_moving_b(axes, short_of));
  EXPECT_GT(depth_after_moving_b(axes, short_of, 0.0), 0);
}

// Moved by less than the least overlap, whichever way, B still overlaps A,
// and the least overlap alone says so: every axis then leaves a positive
// depth. Moved that far along the best axis, it leaves none, and the bound
// says nothing.
TEST(ExactDepth, ShortOfTheLeastOverlapBSurelyStillOverlaps) {
  std::vector<Scene> scenes = sphere_cloud_pairs(12, Vec3(0.3, 0.2, 0.5));
  scenes.push_back(box_on_slab());
  scenes.push_back(crossing_needles());
  int surely = 0, colliding = 0;
  for (const Scene& s : scenes) {
    const auto axes = rank_sat_axes(s);
    if (!(axes[0].overlap > 0)) continue;
    ++colliding;
    std::vector<Vec3> ways = {axes[0].normal, -axes[0].normal};
    for (unsigned k = 0; k < 16; ++k) ways.push_back(test::sphere_points(1, 1000 + k)[0].normalized());
    for (const Vec3& way : ways)
      for (const double share : {0.5, 0.999999, 1.0, 1.000001, 1.5}) {
        const Vec3 t = share * axes[0].overlap * way;
        if (!surely_overlapping_after_moving_b(axes, t)) continue;
        ++surely;
        EXPECT_LT(share, 1);
        EXPECT_GT(depth_after_moving_b(axes, t), 0) << "share " << share;
      }
  }
  EXPECT_GE(colliding, 8);
  EXPECT_EQ(surely, colliding * 18 * 2);  // every way at half the least overlap and just short of it
}

// An edge pair's facet of A - B can face either way: moving B against the
// axis of least overlap must meet the facet on the other side.
TEST(ExactDepth, MovingBAgainstAnEdgeAxisMeetsTheFacetBehind) {
  const Quat ridge = test::about(Vec3(1, 0, 0), M_PI / 4), edge_down = test::about(Vec3(0, 1, 0), M_PI / 4);
  const Scene s = scene_of(test::make_case(box_points(0.5, 0.5, 0.5), {Vec3::Zero(), ridge}, box_points(0.5, 0.5, 0.5),
                                           {Vec3(0, 0, std::sqrt(2.0) - 0.1), edge_down}));
  const auto axes = rank_sat_axes(s);
  ASSERT_EQ(axes[0].kind, AxisKind::edge_edge);
  EXPECT_NEAR(exact_depth(s, axes).signed_depth, 0.1, 1e-14);
  // Pushed down, B's top ridge leaves A's bottom ridge after 2 sqrt(2) - 0.1:
  // the same edge directions, the facet of A - B on the other side.
  const double behind = 2 * std::sqrt(2.0) - 0.1;
  EXPECT_GT(depth_after_moving_b(axes, Vec3(0, 0, -(behind - 1e-3))), 0);
  EXPECT_LT(depth_after_moving_b(axes, Vec3(0, 0, -(behind + 1e-3))), 0);
}

TEST(HullGap, EdgeAcrossEdgeIsTheDistanceBetweenTheEdges) {
  // B's lowest edge runs along y, 0.25 above A's top edge along x.
  const Quat edge_down = test::about(Vec3(0, 1, 0), M_PI / 4) * Quat::Identity();
  const Quat ridge = test::about(Vec3(1, 0, 0), M_PI / 4);
  const Scene s = scene_of(test::make_case(box_points(0.5, 0.5, 0.5), {Vec3::Zero(), ridge}, box_points(0.5, 0.5, 0.5),
                                           {Vec3(0, 0, std::sqrt(2.0) + 0.25), edge_down}));
  const HullGap gap = hull_gap(s);
  EXPECT_NEAR(gap.distance, 0.25, 1e-14);
  EXPECT_VEC_NEAR(gap.on_a, Vec3(0, 0, std::sqrt(0.5)), 1e-14);
  EXPECT_VEC_NEAR(gap.on_b, Vec3(0, 0, std::sqrt(0.5) + 0.25), 1e-14);
}

TEST(HullGap, AVertexAboveAFaceIsItsHeight) {
  const Scene s = scene_of(test::make_case(box_points(2, 2, 0.5), {}, test::tetrahedron_points(),
                                           {Vec3(0.3, -0.2, 3), Quat::Identity()}));
  const HullGap gap = hull_gap(s);
  double lowest = INFINITY;
  for (const Vec3& p : s.world_b) lowest = std::min(lowest, p.z());
  EXPECT_NEAR(gap.distance, lowest - 0.5, 1e-14);
  EXPECT_NEAR(gap.on_a.z(), 0.5, 1e-14);
}

// A tetrahedron 0.1 below a 1,000-gon face, under either half of it: the
// gap is 0.1. With room for 512 corners the face was measured by half of
// its loop, and under the other half the gap ran to its chord (F61's
// hulls).
TEST(HullGap, AVertexBelowAnyPartOfAThousandGonFaceIsItsDepth) {
  const std::vector<Vec3> pyramid = test::pyramid_points(1000, 3, 2);
  const std::vector<Vec3> tip_up = {{0, 0, 0}, {-0.2, -0.2, -0.3}, {0.3, -0.1, -0.3}, {0, 0.3, -0.3}};
  for (int k = 0; k < 8; ++k) {
    const Vec3 at(1.5 * std::cos(M_PI * k / 4), 1.5 * std::sin(M_PI * k / 4), -0.1);
    const Scene s = scene_of(test::make_case(pyramid, {}, tip_up, {at, Quat::Identity()}));
    EXPECT_NEAR(hull_gap(s).distance, 0.1, 1e-12) << at.transpose();
  }
}

TEST(ClosestBetweenSegments, ParallelAndSkewAndDegenerate) {
  Vec3 p, q;
  closest_between_segments(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, -1, 1), Vec3(0.5, 1, 1), p, q);
  EXPECT_VEC_NEAR(p, Vec3(0.5, 0, 0), 1e-15);
  EXPECT_VEC_NEAR(q, Vec3(0.5, 0, 1), 1e-15);
  closest_between_segments(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 1), Vec3(3, 0, 1), p, q);
  EXPECT_VEC_NEAR(p, Vec3(1, 0, 0), 1e-15);
  EXPECT_VEC_NEAR(q, Vec3(2, 0, 1), 1e-15);
  closest_between_segments(Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(-1, 2, 0), Vec3(1, 2, 0), p, q);
  EXPECT_VEC_NEAR(q, Vec3(0, 2, 0), 1e-15);
}

// Two edges 4000 long, 1e-6 rad apart, one 1 above the other: where they
// cross along the common normal is set by the geometry to the inputs'
// rounding over the sine (about 1e-6 here). The textbook denominator
// a e - b^2 cancels to eps over the sine squared and put the point 1.95 off
// at 1e-7 rad; the cross products keep it to eps over the sine (F40).
TEST(ClosestBetweenSegments, NearlyParallelEdgesCrossWhereTheGeometrySays) {
  for (const double angle : {1e-4, 1e-6, 1e-7}) {
    const Vec3 half(2000 * std::cos(angle), 2000 * std::sin(angle), 0);
    const Vec3 middle(2000, 0, 1);
    Vec3 p, q;
    closest_between_segments(Vec3(0, 0, 0), Vec3(4000, 0, 0), middle - half, middle + half, p, q);
    EXPECT_NEAR(p.x(), 2000, 1e-5) << "at " << angle << " rad";
    EXPECT_NEAR(q.x(), 2000, 1e-5) << "at " << angle << " rad";
    EXPECT_NEAR(q.z() - p.z(), 1, 1e-12);
    closest_between_segments(middle - half, middle + half, Vec3(0, 0, 0), Vec3(4000, 0, 0), q, p);
    EXPECT_NEAR(p.x(), 2000, 1e-5) << "swapped, at " << angle << " rad";
  }
}

TEST(MinkowskiOracle, MovingBByTheDepthAlongTheNormalLeavesThemTouching) {
  const Scene s = box_on_slab();
  std::string error;
  const auto md = MinkowskiDifference::build(s.world_a, s.world_b, error);
  EXPECT_GT(md->depth_of(Vec3(0, 0, 0.0999)), 0);
  EXPECT_NEAR(md->depth_of(Vec3(0, 0, 0.1)), 0, 1e-15);
  EXPECT_LT(md->depth_of(Vec3(0, 0, 0.1001)), 0);
}

TEST(BruteForceSat, RanksTheFaceAxisFirstWithItsOverlap) {
  const auto axes = rank_sat_axes(box_on_slab());
  ASSERT_FALSE(axes.empty());
  EXPECT_NEAR(axes[0].overlap, 0.1, 1e-15);
  EXPECT_VEC_NEAR(axes[0].normal, Vec3(0, 0, 1), 1e-15);
  EXPECT_FALSE(has_axis_tie(axes, 1e-9, least_reverse_overlap(axes)));
}

TEST(BruteForceSat, CoincidentCubesTieBetweenOppositeAxes) {
  const Scene s = scene_of(test::make_case(box_points(1, 1, 1), {}, box_points(1, 1, 1), {}));
  const auto axes = rank_sat_axes(s);
  EXPECT_TRUE(has_axis_tie(axes, 1e-9, least_reverse_overlap(axes)));
}

// Two boxes turned by one rotation: their edges in three directions, each
// pair of the same direction parallel to rounding (a cross product of 1e-16,
// not zero), spans no axis; the 96 pairs of different directions each give
// one unit axis.
TEST(BruteForceSat, EdgesParallelToRoundingSpanNoAxis) {
  const Quat turn = Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
  const Scene s = scene_of(test::make_case(box_points(1, 1, 1), {Vec3::Zero(), turn}, box_points(0.5, 0.7, 0.9),
                                           {Vec3(0.3, 0.2, 0.1), turn}));
  int edge_axes = 0;
  for (const RankedAxis& axis : rank_sat_axes(s))
    if (axis.kind == AxisKind::edge_edge) {
      ++edge_axes;
      EXPECT_NEAR(axis.normal.norm(), 1, 1e-15);
    }
  EXPECT_EQ(edge_axes, 96);
}

// The edge pairs' projections run a row of axes at a time, four points at
// once and the last few one by one: every overlap, either way, is the one
// the plain loop over the points gives, to the bit. Hulls of 4 to 64
// points, whose counts end anywhere within a group of four.
TEST(BruteForceSat, EveryEdgeAxisOverlapsAsMuchAsItsPlainProjectionSays) {
  int edge_axes = 0;
  for (unsigned seed = 1; seed <= 24; ++seed) {
    const int points_a = 4 + static_cast<int>(seed * 7 % 61), points_b = 4 + static_cast<int>(seed * 13 % 61);
    const Scene s = scene_of(test::make_case(test::sphere_points(points_a, seed), {},
                                             test::sphere_points(points_b, 100 + seed),
                                             {Vec3(0.3, 0.2, 0.9), test::about(Vec3(1, 2, 3), 0.1 * seed)}));
    for (const RankedAxis& axis : rank_sat_axes(s)) {
      if (axis.kind != AxisKind::edge_edge) continue;
      ++edge_axes;
      ASSERT_EQ(axis.overlap, directed_overlap(s.world_a, s.world_b, axis.normal))
          << "seed " << seed << ", edges " << axis.feature_a << " and " << axis.feature_b;
      ASSERT_EQ(axis.reverse_overlap, directed_overlap(s.world_b, s.world_a, axis.normal))
          << "seed " << seed << ", edges " << axis.feature_a << " and " << axis.feature_b;
    }
  }
  EXPECT_GT(edge_axes, 50000);
}

// The ranking: every axis within the window of the least overlap comes
// first (at least three), sorted, and axes of equal overlap in the order
// they were written (A's faces, B's faces, then the edge pairs row by row).
// The front is gathered as the axes are written, from those that came
// within the window of the least so far; boxes put many axes at the least
// exactly, some written long after the first, and random clouds put it
// anywhere. The least reverse overlap, found as the axes are written
// (parallel edges, which span no axis, have none), is the list's.
TEST(BruteForceSat, EveryAxisWithinTheWindowOfTheLeastIsRankedFirstInOrder) {
  const Quat turn = Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
  std::vector<Scene> scenes = {
      box_on_slab(), scene_of(test::make_case(box_points(1, 1, 1), {}, box_points(1, 1, 1), {})),
      scene_of(test::make_case(box_points(1, 1, 1), {Vec3::Zero(), turn}, box_points(0.5, 0.7, 0.9),
                               {Vec3(0.3, 0.2, 0.1), turn})),
      scene_of(test::make_case(box_points(1, 2, 3), {}, box_points(1, 2, 3), {Vec3(0, 0, 5.5), Quat::Identity()}))};
  scenes.push_back(crossing_needles());
  for (Scene& clouds : sphere_cloud_pairs(24, Vec3(0.3, 0.2, 0.9))) scenes.push_back(std::move(clouds));
  const auto written = [](const RankedAxis& x) {
    return std::tuple(static_cast<int>(x.kind == AxisKind::face_a ? 0 : x.kind == AxisKind::face_b ? 1 : 2),
                      x.feature_a, x.feature_b);
  };
  int fronts_of_many = 0;
  for (const Scene& s : scenes) {
    double least_reverse = NAN;
    const std::vector<RankedAxis> axes = rank_sat_axes(s, &least_reverse);
    ASSERT_GE(axes.size(), 3u);
    EXPECT_EQ(least_reverse, least_reverse_overlap(axes));
    double least = INFINITY;
    for (const RankedAxis& axis : axes) least = std::min(least, axis.overlap);
    const double limit = least + s.length_tolerance(kRankedWindow);
    size_t near = 0;
    for (const RankedAxis& axis : axes) near += axis.overlap <= limit;
    fronts_of_many += near > 3;
    const size_t front = std::max<size_t>(near, 3);
    for (size_t k = 0; k < axes.size(); ++k) {
      if (k < near) {
        ASSERT_LE(axes[k].overlap, limit) << "axis " << k;
      }
      if (k >= front) {
        ASSERT_GE(axes[k].overlap, axes[front - 1].overlap) << "axis " << k;
      }
      if (k + 1 < front) {
        ASSERT_LE(axes[k].overlap, axes[k + 1].overlap) << "axis " << k;
        if (axes[k].overlap == axes[k + 1].overlap && k + 1 < near) {
          ASSERT_LT(written(axes[k]), written(axes[k + 1])) << "axis " << k;
        }
      }
    }
  }
  EXPECT_GE(fronts_of_many, 3);
}

// Two needles crossing through each other (a minimised case from check)
// overlap by about their thickness along the edge axis either way: n and -n
// are both minimal, and only the reverse overlap shows it.
TEST(BruteForceSat, CrossingNeedlesTieBetweenAnEdgeAxisAndItsReverse) {
  const Scene s = crossing_needles();
  const auto axes = rank_sat_axes(s);
  ASSERT_EQ(axes[0].kind, AxisKind::edge_edge);
  EXPECT_LE(axes[0].reverse_overlap - axes[0].overlap, s.length_tolerance(1e-9));
  EXPECT_TRUE(has_axis_tie(axes, s.length_tolerance(1e-9), least_reverse_overlap(axes)));
}

// Under face-bias a generator may answer along a face axis that is not the
// least; the ties that leave its contacts open are those along that axis.
// In the face-bias variant's case the least axis is an edge pair with no
// tie, and the face axis 5% deeper has a face of each hull along it.
TEST(Ties, AlongAFaceAxisThatIsNotTheLeastAFaceOfEachHullTies) {
  const CaseParse parsed = read_case_file(
      test::corpus_path("variants/face-bias-a-face-of-each-hull-ties-along-a-face-axis-that-is-not-the-least.case"));
  ASSERT_TRUE(parsed.value) << parsed.error;
  const Scene s = scene_of(*parsed.value);
  const auto axes = rank_sat_axes(s);
  const double tie = s.length_tolerance(tol::kTie);
  ASSERT_EQ(axes[0].kind, AxisKind::edge_edge);
  EXPECT_FALSE(classify_ties(s, axes, tie, least_reverse_overlap(axes)).contacts_open());
  const RankedAxis* face = nullptr;
  for (const RankedAxis& axis : axes)
    if (axis.kind != AxisKind::edge_edge && (!face || axis.overlap < face->overlap)) face = &axis;
  ASSERT_NE(face, nullptr);
  ASSERT_LE(face->overlap, 1.05 * axes[0].overlap);
  const Ties along = classify_ties_along(s, axes, face->normal, tie);
  EXPECT_FALSE(along.direction);
  EXPECT_TRUE(along.feature);
}

// A box turned about two axes and pressed corner first into a slab: along
// the slab's top face nothing ties, and a direction along no face leaves
// only the depth determined.
TEST(Ties, AlongAFaceAxisWithNoFaceOfTheOtherHullNothingTies) {
  const Scene s = scene_of(test::make_case(box_points(2, 2, 0.5), {}, box_points(0.5, 0.5, 0.5),
                                           {Vec3(0.1, 0.2, 1.1), test::about(Vec3(1, 0, 0), 0.3) *
                                                                     test::about(Vec3(0, 1, 0), 0.2)}));
  const auto axes = rank_sat_axes(s);
  const double tie = s.length_tolerance(tol::kTie);
  const Ties along = classify_ties_along(s, axes, Vec3(0, 0, 1), tie);
  EXPECT_FALSE(along.any());
  EXPECT_TRUE(classify_ties_along(s, axes, Vec3(1, 1, 1).normalized(), tie).direction);
}

// A sheet whose two sides meet at 1.3e-8 rad pokes its corner 2.02 into a
// tetrahedron's face. Within the first-touching 1% of that depth the
// corner's edges (rising 0.25 and 0.49 along n per unit) hold the region to
// under 0.1; the planes' slack alone let a point of A's edge 4.9 past the
// knife edge in, and the region reached 9.6 (h10, manifuzz fuzz).
// The first-touching region of a corpus case along its least-overlap axis,
// as spans-contact-region takes it; nullopt when the case does not read.
std::optional<ContactRegion> first_touching_region(const std::string& file) {
  const CaseParse parsed = read_case_file(test::corpus_path(file));
  if (!parsed.value) {
    ADD_FAILURE() << parsed.error;
    return std::nullopt;
  }
  const Scene s = scene_of(*parsed.value);
  const RankedAxis best = rank_sat_axes(s).front();
  const Vec3 first_touch = tol::kRegionFirstTouch * best.overlap * best.normal;
  return contact_region(s, best.normal, first_touch, s.length_tolerance(tol::kRegionSlack));
}

// A sliver tetrahedron rests by its corner on a face of another whose
// corner lies 0.03 away; its bottom face tilts 1.2e-7 from the other's top.
// The region that touched first grows about that corner as B comes down:
// the region at 99% of the depth is the one at 99.5% twice as large, and
// its centroid twice as far from the corner. B's face beside the edge that
// bounds the region is 15,000 long and 0.03 wide at the corner, its plane
// 2.3e-8 off that edge 90 from the corner, and the edge's crossing with
// A's top there, held to B's planes too, was refused: the region at 99%
// lost that corner, a triangle down to a sliver, its centroid 0.54 of the
// way from the corner (h30).
TEST(ContactRegion, ARegionAboutACornerKeepsTheCrossingOnAnEdgeOfASkinnyFace) {
  const CaseParse parsed = read_case_file(test::corpus_path(
      "regressions/h30-a-crossing-on-the-edge-of-a-face-0-03-wide-at-one-end-lost-from-the-first-touching-region.case"));
  ASSERT_TRUE(parsed.value) << parsed.error;
  const Scene s = scene_of(*parsed.value);
  const RankedAxis best = rank_sat_axes(s).front();
  const double slack = s.length_tolerance(tol::kRegionSlack);
  const auto region_at = [&](double fraction) {
    return contact_region(s, best.normal, fraction * best.overlap * best.normal, slack);
  };
  const ContactRegion first = region_at(0.99), closer = region_at(0.995);
  ASSERT_EQ(first.corners.size(), 3u);
  ASSERT_EQ(closer.corners.size(), 3u);
  EXPECT_GT(convex_hull_area_2d(first.corners), 3.9 * convex_hull_area_2d(closer.corners));
  // The corner they share is B's deepest vertex.
  Vec3 u, v;
  plane_basis(best.normal, u, v);
  const Vec3& deepest = s.world_b[3];
  const Eigen::Vector2d corner(u.dot(deepest), v.dot(deepest));
  const double far = (first.centroid - corner).norm(), near = (closer.centroid - corner).norm();
  EXPECT_NEAR(far / near, 2, 0.02);
}

TEST(ContactRegion, AKnifeEdgedSheetDoesNotReachPastItsEdge) {
  const auto region = first_touching_region("regressions/h10-a-knife-edged-sheet-at-the-origin.case");
  ASSERT_TRUE(region && !region->empty);
  EXPECT_LT(region->width, 0.1);
}

// A sheet 5e-4 thick, 0.3 deep under a top folded by 1.4e-3 rad, lies
// wholly within the first-touching slab: the region is bounded by the sheet
// alone, with no corner on either half of the fold, and still lies against
// both (h12).
TEST(ContactRegion, ASheetWithinTheFirstTouchingSlabLiesAgainstBothHalvesOfAFold) {
  const auto region =
      first_touching_region("regressions/h12-a-sheet-within-the-first-touching-slab-under-a-folded-top.case");
  ASSERT_TRUE(region && !region->empty);
  EXPECT_EQ(region->facing_faces_b, 2);
  EXPECT_EQ(region->facing_faces_a, 1);
}

// The corners as contact_region finds them: every vertex and every
// crossing of every edge with every plane, each held to the other hull
// within the slack, none passed by.
std::vector<Eigen::Vector2d> corners_crossing_every_plane(const Scene& s, const Vec3& n, const Vec3& shift_b,
                                                         double slack) {
  struct Side {
    const Hull& hull;
    const Pose& pose;
    const std::vector<Vec3>& world;
    Vec3 shift;
    std::vector<Vec3> normals;
    std::vector<double> offsets;
    double height(size_t f, const Vec3& p) const { return normals[f].dot(p) - offsets[f]; }
  };
  Side a{s.hull_a, s.pose_a, s.world_a, Vec3::Zero(), {}, {}}, b{s.hull_b, s.pose_b, s.world_b, shift_b, {}, {}};
  for (Side* side : {&a, &b})
    for (int f = 0; f < side->hull.face_count(); ++f) {
      const Vec3 normal = side->pose.rotate(side->hull.face_normal(f));
      side->normals.push_back(normal);
      side->offsets.push_back(normal.dot(side->pose.to_world(side->hull.vertex(side->hull.face_vertex(f, 0))) + side->shift));
    }
  const auto holds = [&](const Side& other, const Vec3& p, size_t on_plane) {
    double outside = -INFINITY;
    for (size_t f = 0; f < other.normals.size(); ++f)
      if (f != on_plane) outside = std::max(outside, other.height(f, p));
    return outside <= -slack ||
           (outside <= slack && signed_distance(other.hull, other.pose, p - other.shift) <= slack);
  };
  std::vector<Vec3> corners;
  for (const auto& [own, other] : {std::pair<const Side&, const Side&>{a, b}, {b, a}}) {
    for (const Vec3& w : own.world)
      if (holds(other, w + own.shift, SIZE_MAX)) corners.push_back(w + own.shift);
    for (const HullEdge& e : own.hull.edges()) {
      const Vec3 p = own.world[e.v0] + own.shift, q = own.world[e.v1] + own.shift;
      for (size_t f = 0; f < other.normals.size(); ++f) {
        const double dp = other.height(f, p), dq = other.height(f, q);
        if ((dp > 0) == (dq > 0) || dp == dq) continue;
        const Vec3 x = p + (dp / (dp - dq)) * (q - p);
        if (holds(other, x, f)) corners.push_back(x);
      }
    }
  }
  Vec3 u, v;
  plane_basis(n, u, v);
  std::vector<Eigen::Vector2d> projected;
  for (const Vec3& c : corners) projected.emplace_back(u.dot(c), v.dot(c));
  return convex_hull_2d(projected);
}

// contact_region passes by an edge beyond one plane of the other hull all
// along; the corners are still those of every edge crossed with every
// plane, to the bit. A box rests on another turned about n, its bottom
// within the slack above the other's top, on it, or just into it (where
// an edge within the slack beyond a plane still crosses the others), and
// tilted through the top.
TEST(ContactRegion, CornersAreThoseOfEveryEdgeCrossedWithEveryPlane) {
  const double slack = 1e-6;
  int compared = 0;
  for (const double turn : {0.0, 0.3, 0.7854})
    for (const double tilt : {0.0, 1e-7, 0.05})
      for (const double lift : {-0.2, -2 * slack, -0.5 * slack, 0.0, 0.5 * slack, 0.9 * slack}) {
        const Quat orientation = test::about(Vec3(1, 0.3, 0).normalized(), tilt) * test::about(Vec3(0, 0, 1), turn);
        const Scene s = scene_of(test::make_case(box_points(1, 1, 1), {Vec3(0.1, -0.2, 0.3), Quat::Identity()},
                                                 box_points(0.8, 0.6, 0.5),
                                                 {Vec3(0.5, 0.2, 0.3 + 1.5 + lift), orientation}));
        const Vec3 n(0, 0, 1);
        const ContactRegion region = contact_region(s, n, Vec3::Zero(), slack);
        const std::vector<Eigen::Vector2d> expected = corners_crossing_every_plane(s, n, Vec3::Zero(), slack);
        ASSERT_EQ(region.corners.size(), expected.size()) << "turn " << turn << ", tilt " << tilt << ", lift " << lift;
        for (size_t i = 0; i < expected.size(); ++i)
          EXPECT_TRUE(region.corners[i] == expected[i]) << "turn " << turn << ", tilt " << tilt << ", lift " << lift;
        compared += !expected.empty();
      }
  EXPECT_GT(compared, 30);
}

// spans-contact-region skips a deep contact on the bound before it works
// out the region: the bound must hold of every region it stands for. Over
// every corpus case, along its three least-overlap axes, at the whole
// intersection, halfway and first touch, no region is wider than its bound.
// The sheets of h10 and h12 are there, whose regions are held to the slack
// at a knife edge, and the boxes resting face to face, whose region is the
// whole section.
TEST(ContactRegion, NoRegionOfACorpusCaseIsWiderThanItsBound) {
  int regions = 0;
  for (const char* folder : {"", "regressions", "variants"})
    for (const auto& entry : std::filesystem::directory_iterator(test::corpus_path(folder))) {
      if (entry.path().extension() != ".case") continue;
      const CaseParse parsed = read_case_file(entry.path().string());
      if (!parsed.value) continue;  // the corpus's malformed inputs
      SceneBuild built = make_scene(*parsed.value);
      if (!built.scene) continue;
      const Scene& s = *built.scene;
      const std::vector<RankedAxis> axes = rank_sat_axes(s);
      const double slack = s.length_tolerance(tol::kRegionSlack);
      for (size_t k = 0; k < std::min<size_t>(3, axes.size()); ++k) {
        if (!(axes[k].overlap > 0)) continue;
        for (const double fraction : {0.0, 0.5, tol::kRegionFirstTouch}) {
          const Vec3 shift = fraction * axes[k].overlap * axes[k].normal;
          const ContactRegion region = contact_region(s, axes[k].normal, shift, slack);
          if (region.empty) continue;
          ++regions;
          EXPECT_LE(region.width, region_width_bound(s, axes[k].normal, shift, slack))
              << entry.path().filename() << ", axis " << k << ", shifted " << fraction;
        }
      }
    }
  EXPECT_GT(regions, 100);
}

// The same over every family of the property suite, along the least-overlap
// axis and along any direction.
RC_GTEST_PROP(ContactRegion, NoRegionIsWiderThanItsBound, ()) {
  const props::GeneratedCase c = *props::any_case();
  SceneBuild built = make_scene(c.file);
  RC_PRE(built.scene.has_value());
  const Scene& s = *built.scene;
  const std::vector<RankedAxis> axes = rank_sat_axes(s);
  RC_PRE(!axes.empty() && axes[0].overlap > 0);
  const Vec3 any = Vec3(*rc::gen::inRange(-100, 101), *rc::gen::inRange(-100, 101), *rc::gen::inRange(-100, 101));
  const double slack = s.length_tolerance(tol::kRegionSlack);
  for (const Vec3& n : {axes[0].normal, any.norm() > 0 ? any.normalized() : axes[0].normal})
    for (const double fraction : {0.0, tol::kRegionFirstTouch}) {
      const Vec3 shift = fraction * axes[0].overlap * n;
      const ContactRegion region = contact_region(s, n, shift, slack);
      RC_ASSERT(region.empty || region.width <= region_width_bound(s, n, shift, slack));
    }
}

TEST(LibccdOracle, EpaDirectionIsTheWayToMoveB) {
  const LibccdAnswer answer = ask_libccd(box_on_slab(), /*with_mpr=*/true);
  EXPECT_TRUE(answer.gjk_intersecting);
  ASSERT_TRUE(answer.epa_ok);
  EXPECT_NEAR(answer.epa_depth, 0.1, 1e-7);
  EXPECT_VEC_NEAR(answer.epa_direction, Vec3(0, 0, 1), 1e-6);
  ASSERT_TRUE(answer.mpr_ok);
  EXPECT_NEAR(answer.mpr_depth, 0.1, 1e-6);
}

TEST(LibccdOracle, AnswersTheSameFarFromTheOriginAndAtAnyScale) {
  const LibccdAnswer far = ask_libccd(box_on_slab(Vec3(1e6, -2e6, 3e5)));
  ASSERT_TRUE(far.epa_ok);
  EXPECT_NEAR(far.epa_depth, 0.1, 1e-6);
  const double s = 1e-4;
  const Scene tiny = scene_of(test::make_case(box_points(2 * s, 2 * s, 0.5 * s), {}, box_points(0.5 * s, 0.5 * s, 0.5 * s),
                                              {Vec3(0, 0, 0.9 * s), Quat::Identity()}));
  const LibccdAnswer small = ask_libccd(tiny);
  ASSERT_TRUE(small.epa_ok);
  EXPECT_NEAR(small.epa_depth / s, 0.1, 1e-6);
}

// Two tetrahedra touching by 1.5e-42: libccd's EPA answered depth 0 along
// (inf, inf, inf). An answer without a direction is EPA failing, and the
// invariants then skip its bounds (h11, manifuzz fuzz: the overlap along
// the NaN direction, -inf, failed the built-in's depth).
TEST(LibccdOracle, AnAnswerWithoutADirectionIsNoAnswer) {
  const std::string file = "regressions/h11-epa-answers-no-direction-at-a-touching-case.case";
  const CaseParse parsed = read_case_file(test::corpus_path(file));
  ASSERT_TRUE(parsed.value) << parsed.error;
  const LibccdAnswer answer = ask_libccd(scene_of(*parsed.value), true);
  EXPECT_TRUE(!answer.epa_ok || answer.epa_direction.allFinite());
  EXPECT_TRUE(!answer.mpr_ok || answer.mpr_direction.allFinite());
}

// Two boxes nearly concentric, turned alike to 1e-15, one corner of B moved
// by 1e-5: libccd's EPA never met its tolerance and never returned, and
// every command hung in the oracle (h14, manifuzz fuzz). With a budget of
// support points it returns, and its answer counts as none.
TEST(LibccdOracle, AnEpaThatWouldNeverEndIsCutOffAndGivesNoAnswer) {
  const std::string file = "regressions/h14-libccd-s-epa-never-ends-on-two-nearly-concentric-boxes.case";
  const CaseParse parsed = read_case_file(test::corpus_path(file));
  ASSERT_TRUE(parsed.value) << parsed.error;
  const LibccdAnswer answer = ask_libccd(scene_of(*parsed.value), true);
  EXPECT_TRUE(answer.gjk_intersecting);
  EXPECT_FALSE(answer.epa_ok);
}

TEST(LibccdOracle, SeparatedHullsDoNotIntersect) {
  const Scene s = scene_of(test::make_case(box_points(0.5, 0.5, 0.5), {}, box_points(0.5, 0.5, 0.5),
                                           {Vec3(1.5, 0, 0), Quat::Identity()}));
  const LibccdAnswer answer = ask_libccd(s);
  EXPECT_FALSE(answer.gjk_intersecting);
  EXPECT_FALSE(answer.epa_ok);
  EXPECT_TRUE(libccd_intersecting(s, Vec3(-0.6, 0, 0)));
}


// The two exact oracles, over every family of the property suite: the least
// overlap over every axis (what the suite uses) and Qhull's hull of the
// vertex differences (the contract's example) give one depth, and one side,
// and agree on how deep B still is when moved.
RC_GTEST_PROP(ExactOracles, LeastOverlapAndQhullsMinkowskiDifferenceAgree, ()) {
  const props::GeneratedCase c = *props::any_case();
  SceneBuild built = make_scene(c.file);
  RC_PRE(built.scene.has_value());
  const Scene& s = *built.scene;
  std::string error;
  const auto difference = MinkowskiDifference::build(s.world_a, s.world_b, error);
  RC_ASSERT(difference.has_value());
  const ExactDepth qhull = difference->at_origin();
  const auto axes = rank_sat_axes(s);
  const ExactDepth exact = exact_depth(s, axes);
  const double tol = s.length_tolerance(tol::kDepth);
  RC_TAG(exact.colliding ? "colliding" : "separated");
  if (std::abs(exact.signed_depth) <= tol) return;  // touching: either side
  RC_ASSERT(qhull.colliding == exact.colliding);
  if (!exact.colliding) {
    // Outside, Qhull's planes bound the gap from below.
    RC_ASSERT(qhull.signed_depth >= exact.signed_depth - tol);
    return;
  }
  RC_ASSERT(std::abs(qhull.signed_depth - exact.signed_depth) <= tol);
  // `separates` moves B: halfway out along the normal both say how deep B
  // still is, the same depth (the facets of A - B are the same planes).
  const Vec3 halfway = 0.5 * exact.signed_depth * exact.normal;
  RC_ASSERT(std::abs(difference->depth_of(halfway) - depth_after_moving_b(axes, halfway)) <= tol);
}

}  // namespace
}  // namespace mfz
